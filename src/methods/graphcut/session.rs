//! The graph-cut texture session: `step()` places one patch (section 4 then section 3) and
//! reports it; the session ends after the output is covered and the refinement patches are
//! placed, or when no unused offset is left.

use super::anatomy::{CostSurface, GraphView};
use super::canvas::Patch;
use super::options::{Blend, Options};
use super::region::{Candidate, Region};
use super::synthesis::Synthesis;
use crate::core::{Error, Image, Result};
use crate::methods::transfer::SourceMap;

/// What a step did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Event {
    /// True once the session has nothing left to do (this step may still have placed a patch).
    pub done: bool,
    /// The patch placed by this step (None when nothing could be placed).
    pub patch: Option<Patch>,
    /// Its rectangle in the output: left, top, width, height (may run past the border when
    /// wrapping).
    pub rect: (i64, i64, usize, usize),
    /// The error region it had to cover.
    pub region: Region,
    /// Output pixels the new patch took (0 when none was placed).
    pub pixels_taken: usize,
    /// Cost of this placement's min cut (0 when no patch was placed).
    pub cut_cost: f64,
    /// Whether every output pixel has been covered.
    pub covered: bool,
    /// Cost of all seams in the output.
    pub total_seam_cost: f64,
    /// Patches placed so far, this step's included.
    pub patches_placed: usize,
}

/// The patch a placement choice drew, and what it drew from when that was not the scored
/// candidates with their own costs (feature-guided placement draws among the best by colour, by
/// colour plus feature cost): the placement anatomy shows eq. 3's probabilities over these.
pub struct Drawn {
    pub patch: Patch,
    pub pool: Option<Vec<Candidate>>,
}

impl From<Patch> for Drawn {
    fn from(patch: Patch) -> Drawn {
        Drawn { patch, pool: None }
    }
}

/// A running graph-cut synthesis.
pub struct Session {
    synthesis: Synthesis,
    refinements_done: usize,
    finished: bool,
    last_region: Option<Region>,
    last: Option<Event>,
    /// The cost surface of the last placement, while the anatomy is recorded.
    last_costs: Option<CostSurface>,
}

impl Session {
    /// A session over `exemplar`; fails on a bad option or an output beyond the memory budget.
    pub fn new(exemplar: &Image, options: Options) -> Result<Session> {
        Ok(Session {
            synthesis: Synthesis::new(exemplar, options)?,
            refinements_done: 0,
            finished: false,
            last_region: None,
            last: None,
            last_costs: None,
        })
    }

    /// A session whose patches come from any of `exemplars`, each with its transformed
    /// versions: every placement's candidates range over all of them, and each patch knows its
    /// exemplar ([`Session::exemplar_map`]). Exemplars with fewer channels are widened to the
    /// most any has.
    pub fn with_exemplars(exemplars: &[Image], options: Options) -> Result<Session> {
        Ok(Session::from_synthesis(Synthesis::with_exemplars(
            exemplars, options,
        )?))
    }

    /// Which exemplar each output pixel shows (`None` where no patch covered it yet).
    #[must_use]
    pub fn exemplar_map(&self) -> Vec<Option<u32>> {
        let s = &self.synthesis;
        (0..s.canvas.width * s.canvas.height)
            .map(|i| s.patch_of(i).map(|p| s.sources[p.source as usize].exemplar))
            .collect()
    }

    /// A session over a synthesis set up by the caller (e.g. with sources of its own).
    #[must_use]
    pub fn from_synthesis(synthesis: Synthesis) -> Session {
        Session {
            synthesis,
            refinements_done: 0,
            finished: false,
            last_region: None,
            last: None,
            last_costs: None,
        }
    }

    /// The sources and the canvas (output, labels, seams) of the synthesis so far.
    #[must_use]
    pub fn synthesis(&self) -> &Synthesis {
        &self.synthesis
    }

    /// The synthesis, for tests and tools that score or place by hand between steps.
    pub fn synthesis_mut(&mut self) -> &mut Synthesis {
        &mut self.synthesis
    }

    /// Whether the session has ended: the output covered and refined, or no offset left.
    #[must_use]
    pub fn is_done(&self) -> bool {
        self.finished
    }

    /// Records (or stops recording) each placement's cost surface and graph for the page's
    /// placement anatomy; off by default, since the graph view costs a few buffers per placement.
    pub fn set_anatomy(&mut self, on: bool) {
        self.synthesis.record_anatomy = on;
        if !on {
            self.last_costs = None;
            self.synthesis.last_graph = None;
        }
    }

    /// The cost surface of the last placement (recorded while the anatomy is on).
    #[must_use]
    pub fn placement_costs(&self) -> Option<&CostSurface> {
        self.last_costs.as_ref()
    }

    /// The graph of the last placement (recorded while the anatomy is on).
    #[must_use]
    pub fn placement_graph(&self) -> Option<&GraphView> {
        self.synthesis.last_graph.as_ref()
    }

    /// The error region of the last placement.
    #[must_use]
    pub fn error_region(&self) -> Option<Region> {
        self.last_region
    }

    /// Places one patch.
    pub fn step(&mut self) -> Result<Event> {
        self.step_with(|s, scored| s.choose(scored).map(Drawn::from))
    }

    /// Places one patch, chosen among the scored candidates by `choose` instead of eq. 3 alone
    /// (feature-guided placement adds its own cost). `None` ends the session.
    pub fn step_with(
        &mut self,
        choose: impl FnOnce(&mut Synthesis, &[Candidate]) -> Option<Drawn>,
    ) -> Result<Event> {
        if self.finished {
            return Ok(self.last.expect("a finished session has stepped"));
        }
        let s = &mut self.synthesis;
        let was_covered = s.canvas.is_covered();
        let region = s.error_region();
        s.draw_windows();
        let candidates = s.candidates(region);
        let scored = s.score(region, &candidates)?;
        let drawn = choose(s, &scored);
        let chosen = drawn.as_ref().map(|d| d.patch);
        let mut event = Event {
            done: false,
            patch: chosen,
            rect: (0, 0, 0, 0),
            region,
            pixels_taken: 0,
            cut_cost: 0.0,
            covered: was_covered,
            total_seam_cost: s.canvas.total_seam_cost(),
            patches_placed: s.canvas.patches.len(),
        };
        self.last_region = Some(region);
        self.last_costs = if s.record_anatomy {
            let temperature = f64::from(s.options.k) * f64::from(s.sigma).powi(2);
            let wrap = s.canvas.wrap.then_some((s.canvas.width, s.canvas.height));
            let anchor = (region.x as i64, region.y as i64);
            CostSurface::new(
                &scored,
                drawn.and_then(|d| d.pool).as_deref(),
                chosen.map(|p| (p.tx, p.ty)),
                temperature,
                anchor,
                wrap,
            )
        } else {
            None
        };
        let Some(patch) = chosen else {
            // No unused offset covers the region: nothing more can be done.
            self.finished = true;
            event.done = true;
            self.last = Some(event);
            return Ok(event);
        };
        // Over a fully covered region, force the region's centre to take the new patch so that a
        // placement cannot be rejected whole (section 3.2).
        let centre = ((region.y + region.height / 2) % s.canvas.height) * s.canvas.width
            + (region.x + region.width / 2) % s.canvas.width;
        let force: &[usize] = if was_covered { &[centre] } else { &[] };
        let placed = s.place(patch, force, &[])?;
        let (pw, ph) = s.patch_extent(patch.source as usize);
        event.rect = (i64::from(patch.tx), i64::from(patch.ty), pw, ph);
        event.pixels_taken = placed.pixels_taken;
        event.cut_cost = placed.cut_cost;
        event.covered = s.canvas.is_covered();
        event.total_seam_cost = s.canvas.total_seam_cost();
        event.patches_placed = s.canvas.patches.len();
        if was_covered {
            self.refinements_done += 1;
        }
        if event.covered && self.refinements_done >= s.options.refinement_patches {
            self.finished = true;
            event.done = true;
        }
        self.last = Some(event);
        Ok(event)
    }

    /// The exemplar pixel each output pixel shows (see `crate::methods::transfer`): exact, from
    /// the labels and the patches' offsets; pixels no patch covered yet have none. Only for a
    /// session of the exemplar alone (no rotated, mirrored or scaled sources, whose pixels are
    /// not the exemplar's).
    pub fn source_map(&self) -> Result<SourceMap> {
        let s = &self.synthesis;
        if s.sources.len() != 1 {
            return Err(Error::InvalidParameter {
                name: "transfer",
                reason: format!(
                    "needs a session of the exemplar alone; this one has {} sources (rotations, \
                     mirrors or scales)",
                    s.sources.len()
                ),
            });
        }
        let (w, h) = (s.canvas.width, s.canvas.height);
        let source = &s.sources[0];
        SourceMap::new(
            (w, h),
            (source.width(), source.height()),
            (0..w * h).map(|i| {
                s.patch_of(i)
                    .and_then(|p| s.source_coords(p, i % w, i / w))
            }),
        )
    }

    /// The output with the chosen blending applied.
    pub fn output(&self) -> Result<Image> {
        match self.synthesis.options.blend {
            Blend::None => Ok(self.synthesis.canvas.pixels.clone()),
            Blend::Feather => Ok(self.synthesis.feathered()),
            Blend::Spline => self.synthesis.splined(),
        }
    }
}
