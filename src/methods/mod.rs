//! Layer 3: one module per paper's feature set, each a progressive session built on the solvers.

pub mod design;
pub mod features;
pub mod flow;
pub mod graphcut;
pub mod inpainting;
pub mod optimization;
pub mod quality;
#[cfg(test)]
mod several_tests;
pub mod transfer;
#[cfg(test)]
mod transfer_tests;
pub mod video;
