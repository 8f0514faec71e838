//! Flow fields and flow-guided texture animation (Kwatra et al. 2005, section 4.1): built-in and
//! caller-given flow fields, the backward warp, the naive warp baseline of Fig. 7, and the
//! frame-by-frame session that synthesises each frame under the flow's soft constraint.

pub mod field;
pub mod generators;
pub mod memory;
pub mod options;
pub mod session;
pub mod setup;
pub mod warp;

#[cfg(test)]
mod anatomy_tests;
#[cfg(test)]
mod tests;

pub use field::FlowField;
pub use generators::{Component, FlowKind, FlowSpec};
pub use options::{FlowOptions, FlowSource};
pub use session::{FlowEvent, FlowEventKind, FlowSession, FrameEnergy};
