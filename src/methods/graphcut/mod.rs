//! Graph-cut textures (Kwatra, Schödl, Essa, Turk & Bobick 2003): the output grows by whole
//! translated copies of the exemplar, each cut along the minimum-cost seam found by max-flow, with
//! old seams remembered so later patches can overwrite them; offsets are chosen at random or by
//! FFT-accelerated SSD matching.

pub mod anatomy;
pub mod blend;
pub mod canvas;
pub mod cost;
pub mod error_regions;
pub mod memory;
pub mod merge;
pub mod options;
pub mod overlap;
pub mod placement;
pub mod region;
pub mod seam;
pub mod seam_graph;
pub mod session;
pub mod source;
pub mod source_window;
pub mod synthesis;
pub mod teaching;

#[cfg(test)]
mod covering_tests;
#[cfg(test)]
mod source_window_tests;
#[cfg(test)]
mod tests;

pub use options::{Blend, Options, Placement, Transforms};
pub use session::{Event, Session};
