//! Texture design (Shen et al. 2009): a designer starts from one small sample and makes a family
//! of textures. Stage 1 deforms the sample globally (`deform`); stage 2 moves texture elements
//! with a brush (`local`: the graph-cut `labelling` of eqs. 1-3, then `poisson_paste`); stage 3
//! synthesises with the wavelet energy (an option of `methods::optimization`); stage 4 fills
//! large textures from the designed ones, layer by layer (`layers`); and any image can be made
//! cyclic (`tileable`, section 4).

pub mod deform;
pub mod labelling;
pub mod layers;
pub mod local;
pub mod memory;
pub mod poisson_paste;

pub use deform::{Deformation, DeformationRanges, Steps, deform};
pub use labelling::LabellingWeights;
pub use local::{BrushOptions, LocalDeformation, Stroke, StrokeResult};
pub mod tileable;
pub use tileable::{Tileable, TileableEvent, TileableOptions, TileableSession, make_tileable};
