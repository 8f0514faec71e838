//! The inpainting session: the graph-cut fill of `super::fill`, a patch per step, then texture
//! optimisation (Kwatra et al. 2005, Algorithm 2) over the hole and a margin of known pixels,
//! which are hard constraints, coarse to fine, an EM iteration per step. Pixels outside the hole
//! are never changed.

use super::fill::{Fill, FillSource};
use super::mask::{Hole, Rect};
use super::options::Options;
use crate::core::{Error, Image, Result};
use crate::methods::optimization::{self, SoftConstraints, Start};

/// How far beyond the working region the image is its own exemplar for the optimisation.
pub const SOURCE_REACH: usize = 256;

/// The smallest image side accepted (texture optimisation's smallest exemplar).
pub const MIN_SIDE: usize = optimization::options::MIN_EXEMPLAR_SIDE;

/// Which pass a step belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stage {
    /// The graph-cut fill.
    Fill,
    /// The texture optimisation.
    Optimization,
}

impl Stage {
    /// The name used in events ("fill", "optimization").
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Stage::Fill => "fill",
            Stage::Optimization => "optimization",
        }
    }
}

/// What a step did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EventKind {
    /// The fill placed a patch.
    Placed,
    /// Part of an optimisation iteration (large regions).
    Part,
    /// The first iteration of an optimisation level.
    Level,
    /// Another iteration within the level.
    Iteration,
    /// Finished.
    Done,
}

/// The report of one step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Event {
    /// What the step did; [`EventKind::Done`] on the last step and any after it.
    pub kind: EventKind,
    /// The pass the step belongs to.
    pub stage: Stage,
    /// Patches the fill placed so far.
    pub patches_placed: usize,
    /// Hole pixels the fill has filled, of `hole_pixels`.
    pub pixels_filled: usize,
    /// Pixels in the hole.
    pub hole_pixels: usize,
    /// The placement of this step: its corner in the image, and the minimum cut's cost.
    pub patch: Option<PlacedPatch>,
    /// The optimisation's level (0-based) and level count, iteration within the level, and
    /// texture energy (see `optimization::Event`); `None` during the fill.
    pub level: Option<usize>,
    /// Levels of the optimisation's schedule.
    pub level_count: Option<usize>,
    /// Iteration within the level, 1-based.
    pub iteration: Option<usize>,
    /// Texture energy of the optimisation's iteration.
    pub energy: Option<f64>,
}

/// A patch of the fill, in image coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlacedPatch {
    /// Left column of the patch in the image.
    pub x: usize,
    /// Top row of the patch in the image.
    pub y: usize,
    /// Side of the patch.
    pub size: usize,
    /// Left column of the source window it copies (in the exemplar, or in the image).
    pub source_x: usize,
    /// Top row of the source window.
    pub source_y: usize,
    /// Cost of the placement's minimum cut.
    pub cut_cost: f64,
}

/// A running inpainting.
pub struct Session {
    options: Options,
    image: Image,
    hole: Hole,
    /// The part of the image worked on: the hole's bounds and a margin.
    region: Rect,
    fill: Fill,
    /// The optimisation, made when the session is (so that its options fail early) and run
    /// once the fill is done; with its exemplar's corner in the image (`None`: a separate
    /// exemplar).
    optimization: Option<optimization::Session>,
    optimizing: bool,
    done: bool,
    last: Option<Event>,
}

impl Session {
    /// Fills the pixels of `image` where `mask` (one byte per pixel) is non-zero, from the rest
    /// of the image, or from `exemplar` when one is given.
    pub fn new(
        image: &Image,
        mask: &[u8],
        exemplar: Option<&Image>,
        options: Options,
    ) -> Result<Session> {
        options.validate()?;
        let (w, h) = (image.width(), image.height());
        if w < MIN_SIDE || h < MIN_SIDE {
            return Err(Error::InvalidSize {
                what: "image",
                width: w,
                height: h,
                reason: format!("inpainting needs at least {MIN_SIDE}x{MIN_SIDE}"),
            });
        }
        let hole = Hole::new(w, h, mask)?;
        if let Some(e) = exemplar
            && e.channels() != image.channels()
        {
            return Err(Error::InvalidParameter {
                name: "exemplar",
                reason: format!(
                    "has {} channels, the image {}",
                    e.channels(),
                    image.channels()
                ),
            });
        }
        let margin = (2 * options.margin()).max(options.patch_size);
        let region = hole.bounds().grown(margin, w, h);
        let crop = image.crop(region.x, region.y, region.width, region.height)?;
        let inside = hole.within(region);
        let known: Vec<bool> = inside.iter().map(|&m| !m).collect();
        let source = match exemplar {
            Some(e) => FillSource {
                image: e.clone(),
                unknown: None,
                region_origin: None,
            },
            None => FillSource {
                image: image.clone(),
                unknown: Some(hole.mask.clone()),
                region_origin: Some((region.x, region.y)),
            },
        };
        let fill = Fill::new(
            crop.clone(),
            known.clone(),
            source,
            options.patch_size,
            options.k,
            options.seed,
        )?;
        let optimization = if options.optimize {
            Some(Self::make_optimization(
                image, &hole, region, crop, &known, exemplar, &options,
            )?)
        } else {
            None
        };
        Ok(Session {
            options,
            image: image.clone(),
            hole,
            region,
            fill,
            optimization,
            optimizing: false,
            done: false,
            last: None,
        })
    }

    /// The texture optimisation of the region: its known pixels hard constraints, its exemplar
    /// the given one or the image around the region with the hole excluded.
    fn make_optimization(
        image: &Image,
        hole: &Hole,
        region: Rect,
        crop: Image,
        known: &[bool],
        exemplar: Option<&Image>,
        options: &Options,
    ) -> Result<optimization::Session> {
        let settings = |levels: usize, sizes: &[usize]| optimization::Options {
            output_width: region.width,
            output_height: region.height,
            seed: options.seed,
            levels,
            neighbourhood_sizes: sizes.to_vec(),
            iterations: options.iterations,
            r: options.r,
            search: options.search,
            completeness: options.completeness,
            histogram_matching: options.histogram_matching,
            start: Start::Patches,
            memory_budget_mib: options.memory_budget_mib,
            ..optimization::Options::default()
        };
        let (levels, sizes) = (options.levels, &options.neighbourhood_sizes);
        let mut session = match exemplar {
            Some(e) => optimization::Session::new(e, settings(levels, sizes))?,
            None => {
                let around = region.grown(SOURCE_REACH, image.width(), image.height());
                let source = image.crop(around.x, around.y, around.width, around.height)?;
                let excluded = hole.within(around);
                // Coarse levels and large neighbourhoods find no neighbourhood outside a large
                // hole in a small image: levels are dropped, coarsest first, then the largest
                // sizes, while one has none.
                let mut sizes = sizes.clone();
                sizes.sort_unstable_by(|a, b| b.cmp(a));
                let mut levels = levels;
                loop {
                    let mut session = optimization::Session::new(&source, settings(levels, &sizes))?;
                    match session.exclude_exemplar(excluded.clone()) {
                        Ok(()) => break session,
                        Err(_) if levels > 1 => levels -= 1,
                        Err(_) if sizes.len() > 1 => {
                            sizes.remove(0);
                        }
                        Err(e) => return Err(e),
                    }
                }
            }
        };
        let mask = known.iter().map(|&k| f32::from(u8::from(k))).collect();
        session.set_constraints(Some(SoftConstraints::hard(crop, mask)?))?;
        session.match_histogram_to_constraint(true);
        Ok(session)
    }

    /// Runs one step: a patch of the fill, or an EM iteration (or part of one) of the
    /// optimisation.
    pub fn step(&mut self) -> Result<Event> {
        if self.done {
            let mut last = self.last.expect("a finished session has stepped");
            last.kind = EventKind::Done;
            return Ok(last);
        }
        let event = if self.optimizing {
            self.optimize()?
        } else {
            self.place()?
        };
        self.last = Some(event);
        Ok(event)
    }

    fn place(&mut self) -> Result<Event> {
        let placed = self.fill.place()?;
        let finished = self.fill.is_done();
        if finished {
            match &mut self.optimization {
                Some(opt) => {
                    opt.start_from(self.fill.pixels().clone())?;
                    self.optimizing = true;
                }
                None => self.done = true,
            }
        }
        let (x, y) = (self.region.x + placed.x, self.region.y + placed.y);
        Ok(Event {
            kind: if self.done {
                EventKind::Done
            } else {
                EventKind::Placed
            },
            stage: Stage::Fill,
            patches_placed: self.fill.patches(),
            pixels_filled: self.hole.count - self.fill.unfilled(),
            hole_pixels: self.hole.count,
            patch: Some(PlacedPatch {
                x,
                y,
                size: self.fill.side(),
                source_x: placed.source_x,
                source_y: placed.source_y,
                cut_cost: placed.cut_cost,
            }),
            level: None,
            level_count: None,
            iteration: None,
            energy: None,
        })
    }

    fn optimize(&mut self) -> Result<Event> {
        let opt = self.optimization.as_mut().expect("optimizing");
        let e = opt.step()?;
        use optimization::EventKind as K;
        let kind = match e.kind {
            K::Part => EventKind::Part,
            K::Level => EventKind::Level,
            K::Iteration => EventKind::Iteration,
            K::Done => EventKind::Done,
        };
        self.done = opt.is_done();
        Ok(Event {
            kind: if self.done { EventKind::Done } else { kind },
            stage: Stage::Optimization,
            patches_placed: self.fill.patches(),
            pixels_filled: self.hole.count,
            hole_pixels: self.hole.count,
            patch: None,
            level: Some(e.level),
            level_count: Some(e.level_count),
            iteration: Some(e.iteration),
            energy: e.energy.is_finite().then_some(e.energy),
        })
    }

    /// The estimated peak working set in bytes: the optimisation's (with its constraint), plus
    /// the image, the region's fill and the fill's source.
    #[must_use]
    pub fn memory_estimate(&self) -> u64 {
        let values = |i: &Image| (i.data().len() * 4) as u64;
        let r = self.region;
        let fill = values(self.fill.pixels()) + (r.width * r.height * 14) as u64;
        let opt = self
            .optimization
            .as_ref()
            .map_or(0, |o| o.working_set(true).bytes());
        2 * values(&self.image) + fill + opt
    }

    /// Whether the session is finished.
    #[must_use]
    pub fn is_done(&self) -> bool {
        self.done
    }

    /// The options the session was made with.
    #[must_use]
    pub fn options(&self) -> &Options {
        &self.options
    }

    /// The hole.
    #[must_use]
    pub fn hole(&self) -> &Hole {
        &self.hole
    }

    /// The part of the image worked on.
    #[must_use]
    pub fn region(&self) -> Rect {
        self.region
    }

    /// The fill (its labels and source coordinates are the teaching view's).
    #[must_use]
    pub fn fill(&self) -> &Fill {
        &self.fill
    }

    /// The optimisation, when the options run one.
    #[must_use]
    pub fn optimization(&self) -> Option<&optimization::Session> {
        self.optimization.as_ref()
    }

    /// The image as it stands: the known pixels as given, the hole as filled so far (pixels the
    /// fill has not reached yet keep the image's values; coarse optimisation levels are shown
    /// up-sampled).
    pub fn output(&self) -> Result<Image> {
        let region = match (&self.optimization, self.optimizing) {
            (Some(opt), true) => opt.output_full_size()?,
            _ => self.fill.pixels().clone(),
        };
        let mut out = self.image.clone();
        let r = self.region;
        for y in 0..r.height {
            for x in 0..r.width {
                if self.hole.mask[(r.y + y) * self.image.width() + r.x + x] {
                    out.pixel_mut(r.x + x, r.y + y)
                        .copy_from_slice(region.pixel(x, y));
                }
            }
        }
        Ok(out)
    }
}
