//! Feature-guided texture synthesis (Wu & Yu 2004): detect curvilinear features (`detect`, with
//! the `bilateral` filter and `thinning`), match them in position and orientation (`matching`),
//! bend the chosen patch so its features meet the placed ones (`alignment`), and grow the texture
//! and its feature map together (`session`; graph-cut placement in `hybrid`, the grown map in
//! `carried`), and count the features outputs break (`broken`).

pub mod alignment;
pub mod bilateral;
pub mod detect;
pub mod matching;
pub mod memory;
pub mod thinning;

pub use detect::{DetectOptions, FeatureKind, FeatureMap, detect};
pub mod broken;
pub mod carried;
pub mod hybrid;
mod options;
mod session;

pub use alignment::WarpKind;
pub use options::{FeatureOptions, FeaturePlacement};
pub use session::{FeatureEvent, FeatureSynthesis, Placement};
