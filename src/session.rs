//! The one interface every method's session shares: built from an exemplar and options, advanced
//! by [`Session::step`] until [`Session::is_done`], its output readable after any step.

use crate::core::{Image, Result, from_rgba8};
use crate::methods::design::TileableSession;
use crate::methods::design::layers::{LayerDesign, LayerEvent};
use crate::methods::design::memory::layers_working_set;
use crate::methods::design::tileable::TileableEvent;
use crate::methods::features::{FeatureEvent, FeatureSynthesis};
use crate::methods::flow::{FlowEvent, FlowSession};
use crate::methods::graphcut::merge::{Merge, MergeEvent};
use crate::methods::{graphcut, inpainting, optimization, video};

/// A progressive synthesis: each [`step`](Session::step) is one unit of work a person would want
/// to see (an EM iteration, a patch placement, a frame), and never blocks for long.
pub trait Session {
    /// What one step did.
    type Event;

    /// Runs one step. Fails only on an internal error; options are checked when the session is
    /// built.
    fn step(&mut self) -> Result<Self::Event>;

    /// Whether the last step has run.
    fn is_done(&self) -> bool;

    /// The output as far as it is made, at its full size.
    fn output(&self) -> Result<Image>;

    /// The estimated peak working set in bytes, what the constructor checked against the
    /// memory budget.
    fn memory_estimate(&self) -> u64;
}

impl Session for optimization::Session {
    type Event = optimization::Event;

    fn step(&mut self) -> Result<Self::Event> {
        optimization::Session::step(self)
    }

    fn is_done(&self) -> bool {
        optimization::Session::is_done(self)
    }

    fn output(&self) -> Result<Image> {
        self.output_full_size()
    }

    fn memory_estimate(&self) -> u64 {
        self.working_set(self.constraints().is_some()).bytes()
    }
}

impl Session for inpainting::Session {
    type Event = inpainting::Event;

    fn step(&mut self) -> Result<Self::Event> {
        inpainting::Session::step(self)
    }

    fn is_done(&self) -> bool {
        inpainting::Session::is_done(self)
    }

    fn output(&self) -> Result<Image> {
        inpainting::Session::output(self)
    }

    fn memory_estimate(&self) -> u64 {
        inpainting::Session::memory_estimate(self)
    }
}

impl Session for graphcut::Session {
    type Event = graphcut::Event;

    fn step(&mut self) -> Result<Self::Event> {
        graphcut::Session::step(self)
    }

    fn is_done(&self) -> bool {
        graphcut::Session::is_done(self)
    }

    fn output(&self) -> Result<Image> {
        graphcut::Session::output(self)
    }

    fn memory_estimate(&self) -> u64 {
        self.synthesis().working_set().bytes()
    }
}

impl Session for Merge {
    type Event = MergeEvent;

    fn step(&mut self) -> Result<Self::Event> {
        Merge::step(self)
    }

    fn is_done(&self) -> bool {
        Merge::is_done(self)
    }

    /// The composite so far (black where no source reaches yet).
    fn output(&self) -> Result<Image> {
        Ok(self.synthesis().canvas.pixels.clone())
    }

    fn memory_estimate(&self) -> u64 {
        self.synthesis().working_set().bytes()
    }
}

impl Session for FlowSession {
    type Event = FlowEvent;

    fn step(&mut self) -> Result<Self::Event> {
        FlowSession::step(self)
    }

    fn is_done(&self) -> bool {
        FlowSession::is_done(self)
    }

    /// The frame being made, or the last one finished.
    fn output(&self) -> Result<Image> {
        self.frame_image()
    }

    fn memory_estimate(&self) -> u64 {
        self.working_set().bytes()
    }
}

impl Session for FeatureSynthesis {
    type Event = FeatureEvent;

    fn step(&mut self) -> Result<Self::Event> {
        FeatureSynthesis::step(self)
    }

    fn is_done(&self) -> bool {
        FeatureSynthesis::is_done(self)
    }

    fn output(&self) -> Result<Image> {
        Ok(self.image().clone())
    }

    fn memory_estimate(&self) -> u64 {
        self.working_set().bytes()
    }
}

impl Session for video::Session {
    type Event = video::Event;

    fn step(&mut self) -> Result<Self::Event> {
        video::Session::step(self)
    }

    fn is_done(&self) -> bool {
        video::Session::is_done(self)
    }

    /// The first output frame; `video::teaching::frame_rgba` gives any other.
    fn output(&self) -> Result<Image> {
        let (w, h, _) = self.size();
        let mut rgba = vec![0u8; w * h * 4];
        video::teaching::frame_rgba(self, 0, &mut rgba)?;
        from_rgba8(w, h, &rgba)?.with_channels(3)
    }

    fn memory_estimate(&self) -> u64 {
        self.working_set().bytes()
    }
}

impl Session for TileableSession {
    type Event = TileableEvent;

    fn step(&mut self) -> Result<Self::Event> {
        TileableSession::step(self)
    }

    fn is_done(&self) -> bool {
        TileableSession::is_done(self)
    }

    /// The image as far as it is made (it shrinks by the overlap at each stitch).
    fn output(&self) -> Result<Image> {
        Ok(self.image().clone())
    }

    fn memory_estimate(&self) -> u64 {
        self.working_set().bytes()
    }
}

impl Session for LayerDesign {
    type Event = LayerEvent;

    fn step(&mut self) -> Result<Self::Event> {
        LayerDesign::step(self)
    }

    fn is_done(&self) -> bool {
        LayerDesign::is_done(self)
    }

    fn output(&self) -> Result<Image> {
        Ok(self.image().clone())
    }

    fn memory_estimate(&self) -> u64 {
        let o = self.options();
        let dims: Vec<(usize, usize)> = self
            .textures()
            .iter()
            .map(|t| (t.width(), t.height()))
            .collect();
        let channels = self.textures().iter().map(Image::channels).max();
        layers_working_set(
            (o.output_width, o.output_height, channels.unwrap_or(4)),
            o.patch_size,
            &dims,
        )
        .bytes()
    }
}
