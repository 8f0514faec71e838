//! Texture optimisation (Kwatra, Essa, Bobick & Kwatra 2005): synthesis as minimisation of a
//! texture energy over overlapping neighbourhoods, by an EM-like alternation of an E-step (the
//! best output for fixed matches) and an M-step (the best matches for a fixed output), with
//! robust IRLS weights, an optional gradient energy, and a coarse-to-fine schedule.

pub mod channel_weights;
pub mod constraints;
pub mod e_step;
pub mod exemplars;
pub mod exclusion;
pub mod features;
pub mod guides;
pub mod histogram;
pub mod initial;
pub mod iteration;
pub mod level;
pub mod m_step;
pub mod memory;
pub mod occurrence;
pub mod options;
pub mod phases;
pub mod queries;
pub mod schedule;
pub mod session;
pub mod teaching;
pub mod wavelet_energy;

#[cfg(test)]
mod channel_weight_tests;
#[cfg(test)]
mod guide_tests;
#[cfg(test)]
mod start_tests;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod wash_out_tests;
#[cfg(test)]
mod wavelet_tests;

pub use constraints::SoftConstraints;
pub use options::{Options, Start};
pub use session::{Event, EventKind, Session};
pub use wavelet_energy::Energy;
