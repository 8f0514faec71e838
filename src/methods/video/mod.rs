//! Graph-cut video textures (Kwatra et al. 2003, section 7): video as an (x, y, t) volume,
//! patches as spatio-temporal blocks, seams as surfaces found by max-flow over 6-connected
//! voxels, with the image version's old-seam nodes, surrounded regions and cost M / M' (eq. 5).
//!
//! - `volume`: the [`Volume`] type; `budget`: the memory budget and its checks;
//! - `source`, `canvas`, `synthesis`, `seam`: the seam graph in 3-D;
//! - `transition` (7.A): frame-pair SSD and the best transition; the loop itself is two
//!   placements of the session;
//! - `placement`: error regions, random temporal (7.B) and spatio-temporal (7.E) offsets,
//!   entire-patch and sub-patch matching (7.C) with the 3-D FFT SSD;
//! - `session`: phases, including 7.D's constrained first and last k frames; `loop_band`: 7.A's
//!   cut coarse to fine; `feather`: section 5's feathering across voxel seams;
//! - `teaching`: per-frame seam overlay and x-t slice.

pub mod anatomy;
pub mod budget;
pub mod canvas;
pub mod feather;
pub mod loop_band;
pub mod options;
pub mod placement;
pub mod procedural;
pub mod seam;
pub mod session;
pub mod source;
pub mod synthesis;
pub mod teaching;
pub mod transition;
pub mod volume;

#[cfg(test)]
mod anatomy_tests;
#[cfg(test)]
mod loop_tests;
#[cfg(test)]
mod tests;

pub use budget::MAX_VOLUME_BYTES;
pub use options::{Blend, Mode, Options, Placement};
pub use session::{Event, Session};
pub use volume::Volume;
