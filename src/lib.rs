//! # texsynth
//!
//! Texture synthesis from a small example image, built as progressive sessions so that every
//! step can be shown: texture optimisation (Kwatra et al. 2005), graph-cut textures and video
//! textures (Kwatra et al. 2003), texture design (Shen et al. 2009) and feature-guided synthesis
//! (Wu & Yu 2004). The same code is the npm package `texsynth-wasm` when compiled to
//! WebAssembly.
//!
//! Every method is a module with `Options` (plain data; where a default differs from its paper,
//! the method's page in `docs/methods/` says so and why), a `Session` built from an exemplar and
//! the options, and the `Event` each step returns; every session implements the [`Session`]
//! trait.
//!
//! ```
//! use texsynth::{Image, Session, graphcut};
//!
//! // A small striped exemplar; `texsynth::decode` reads PNG and JPEG bytes.
//! let exemplar = Image::from_fn(24, 24, 3, |x, y, c| ((x + 2 * y + c) % 7) as f32 / 7.0)?;
//! let options = graphcut::Options {
//!     output_width: 48,
//!     output_height: 48,
//!     ..graphcut::Options::default()
//! };
//! let mut session = graphcut::Session::new(&exemplar, options)?;
//! while !Session::is_done(&session) {
//!     let event = Session::step(&mut session)?;
//!     // event.patches_placed, event.cut_cost, ... : draw the output here to watch it grow
//! }
//! let output = Session::output(&session)?;
//! assert_eq!((output.width(), output.height()), (48, 48));
//! # Ok::<(), texsynth::Error>(())
//! ```
//!
//! The code is layered, each layer depending only on the ones before it: `core` (images,
//! decoding, resampling, pyramids, the seeded random numbers, errors), `solvers` (max-flow,
//! FFT search, nearest-neighbour searches, Poisson, wavelets, thin-plate splines), `methods`
//! (one module per paper) and, in the wasm build only, `bindings` (the JavaScript API). The
//! modules re-exported here are the supported surface; the layers themselves are private (the
//! `internals` feature opens them to the project's benchmarks and fuzz targets; it is not part of
//! the API).
#![warn(missing_docs)]

/// Declares an internal layer: private to the crate, and public (hidden from the docs) with the
/// `internals` feature, which only the project's benchmarks and fuzz targets turn on. Parts of
/// the layers serve only the JS bindings, the tests' oracles or the benchmarks, so dead code is
/// not linted when the layers are private.
macro_rules! layer {
    ($name:ident) => {
        #[cfg(feature = "internals")]
        #[doc(hidden)]
        pub mod $name;
        #[cfg(not(feature = "internals"))]
        #[allow(dead_code, unused_imports)]
        mod $name;
    };
}

#[cfg(target_arch = "wasm32")]
#[doc(hidden)]
pub mod bindings;
layer!(core);
layer!(methods);
mod session;
layer!(solvers);

pub use crate::core::{Error, Image, Result, decode, encode_png, from_rgba8, to_rgba8};
pub use crate::methods::quality::{Quality, quality};
pub use crate::methods::transfer::SourceMap;
pub use crate::session::Session;

/// Texture optimisation (Kwatra et al. 2005): EM over overlapping neighbourhoods, multi-level,
/// with soft constraints.
pub mod optimization {
    pub use crate::methods::optimization::{
        Energy, Event, EventKind, Options, Session, SoftConstraints, Start,
    };
    pub use crate::solvers::nn::Search;
}

/// Graph-cut textures (Kwatra et al. 2003): patches placed by FFT search, joined by min-cut
/// seams; and interactive merging of several images.
pub mod graphcut {
    pub use crate::methods::graphcut::merge::{Merge, MergeEvent};
    pub use crate::methods::graphcut::{Blend, Event, Options, Placement, Session, Transforms};
}

/// Inpainting and uncrop: a hole filled from the image's known part (or an exemplar) by a
/// graph-cut fill, then texture optimisation with the known pixels as hard constraints.
pub mod inpainting {
    pub use crate::methods::inpainting::{
        Border, Event, EventKind, Hole, Options, PlacedPatch, Rect, Session, Stage, extend,
    };
}

/// Flow-guided texture animation (Kwatra et al. 2005, section 4.1).
pub mod flow {
    pub use crate::methods::flow::{
        Component, FlowEvent as Event, FlowEventKind as EventKind, FlowField, FlowKind,
        FlowOptions as Options, FlowSession as Session, FlowSource, FlowSpec,
    };
}

/// Feature-guided synthesis (Wu & Yu 2004): feature maps, orientation-aware matching and
/// patch warping.
pub mod features {
    pub use crate::methods::features::{
        DetectOptions, FeatureEvent as Event, FeatureKind, FeatureMap, FeatureOptions as Options,
        FeaturePlacement as Placement, FeatureSynthesis as Session, WarpKind, detect,
    };
}

/// Graph-cut video textures (Kwatra et al. 2003, section 7).
pub mod video {
    pub use crate::methods::video::{Event, Mode, Options, Placement, Session, Volume};
}

/// Texture design (Shen et al. 2009): global deformations, the brush, layer-based design and
/// cyclic textures.
pub mod design {
    pub use crate::methods::design::{
        BrushOptions, Deformation, DeformationRanges, LocalDeformation, Stroke, StrokeResult,
        deform,
    };

    /// Making an image cyclic (section 4), one graph-cut stitch per step.
    pub mod tileable {
        pub use crate::methods::design::tileable::{
            Tileable, TileableEvent as Event, TileableOptions as Options,
            TileableSession as Session, make_tileable,
        };
    }

    /// Fast layer-based design (stage 4): one row of patches per step.
    pub mod layers {
        pub use crate::methods::design::layers::{
            Layer, LayerDesign as Session, LayerEvent as Event, LayerOptions as Options,
            LayerPlacement as Placement, LayerSearch as Search,
        };
    }
}

// The README's Rust quick start, compiled and run as a doc test.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeQuickStart;
