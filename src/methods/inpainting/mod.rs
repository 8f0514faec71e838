//! Inpainting: filling a hole in an image from its known part (or from a separate exemplar),
//! and uncrop, the same job with the new border of an extended image as the hole. A graph-cut
//! fill placed from the outside in (Kwatra et al. 2003, with the known pixels held by constraint
//! arcs), then texture optimisation over the hole and a margin with the known pixels as hard
//! constraints (Kwatra et al. 2005, Algorithm 2). Pixels outside the hole never change.

pub mod fill;
pub mod mask;
pub mod options;
pub mod session;

#[cfg(test)]
mod tests;

pub use mask::{Border, Hole, Rect, extend};
pub use options::Options;
pub use session::{Event, EventKind, PlacedPatch, Session, Stage};
