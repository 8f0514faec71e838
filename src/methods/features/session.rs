//! Feature-guided texture synthesis (Wu & Yu 2004, section 3): the texture and its feature map
//! grow together, one patch per step, in scan order. Each patch is chosen by the weighted sum of
//! the feature matching cost (eq. 2) and the colour SSD over its L-shaped context region (weight
//! 0.5 each, each divided by its mean over the candidates so that pixels and colours weigh alike),
//! bent by the alignment warp, and merged along the minimum-cut seam of graph-cut textures.
//! Where the exemplar has no oriented features the choice reverts to colour alone, and the event
//! says so.

use super::alignment::{WarpKind, align};
use super::carried::update_canvas_features;
#[cfg(test)]
use super::detect::DetectOptions;
use super::detect::{FeatureMap, detect};
use super::hybrid::{GraphcutFeatures, HybridOptions};
use super::matching::{ContextFeature, FeatureIndex, Region, TAU_MATCH};
use super::memory::{METHOD, working_set};
use super::options::{FeatureOptions, FeaturePlacement};
use crate::core::sample::sample_bicubic;
use crate::core::{Edge, Error, Image, Result, Rng};
use crate::methods::graphcut::Options as GraphcutOptions;
use crate::methods::graphcut::overlap::{ScanWindow, scan_origins};
use crate::methods::graphcut::synthesis::estimate as graphcut_estimate;
use crate::solvers::fft_ssd::{Boundary, SsdSearch};
use crate::solvers::maxflow::Graph;

/// What one step did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FeatureEvent {
    /// Index of the patch placed, 0 for the first.
    pub patch: usize,
    /// Patches the output takes (with graph-cut placement, a lower bound that grows until the
    /// output is covered).
    pub patches: usize,
    /// Where the patch went in the output, and where it came from (input index, top-left).
    pub x: usize,
    /// Top of the patch in the output.
    pub y: usize,
    /// The input the patch came from: 0 the exemplar, then `extra_inputs` in order.
    pub input: usize,
    /// Left of the patch in its input.
    pub source_x: usize,
    /// Top of the patch in its input.
    pub source_y: usize,
    /// Eq. 2 and the mean squared colour difference of the chosen candidate.
    pub feature_cost: f32,
    /// Mean squared colour difference of the chosen candidate.
    pub colour_cost: f32,
    /// Feature pixels in the patch's context region (graph-cut placement: in the feature band).
    pub context_features: usize,
    /// Feature correspondences the warp used (0 with graph-cut placement, which does not warp).
    pub correspondences: usize,
    /// The warp applied to the patch ([`WarpKind::Unavailable`] with graph-cut placement).
    pub warp: WarpKind,
    /// True when the choice used colour only (no oriented features to match).
    pub colour_only: bool,
    /// True on the last step, and on any step after it (which repeats the last event).
    pub done: bool,
}

/// One input (the exemplar or a deformed copy) ready for the scan placement's search.
/// Graph-cut placement keeps its inputs in [`GraphcutFeatures`] alone (its sources and their
/// feature indexes): an index is four distance transforms, and over a 12-megapixel photo a
/// second copy of the inputs would be most of a gigabyte.
struct Input {
    image: Image,
    map: FeatureMap,
    index: FeatureIndex,
}

/// The last placement, for the teaching views.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Placement {
    pub x: usize,
    pub y: usize,
    pub size: usize,
    pub region: Option<Region>,
    /// (output x, y) of a context feature and (output x, y) where its partner lay in the patch
    /// before the warp.
    pub pairs: Vec<((f32, f32), (f32, f32))>,
    /// Displacements every 4 pixels of the patch, row by row ((size + 3) / 4 per side).
    pub grid: Vec<(f32, f32)>,
}

/// A feature-guided synthesis in progress.
pub struct FeatureSynthesis {
    options: FeatureOptions,
    /// The scan placement's inputs (empty under graph-cut placement).
    inputs: Vec<Input>,
    /// Width and height of every input, for the memory estimate.
    input_dims: Vec<(usize, usize)>,
    output: Image,
    filled: Vec<bool>,
    feature: Vec<bool>,
    angle: Vec<f32>,
    origins: Vec<(usize, usize)>,
    next: usize,
    rng: Rng,
    graph: Graph,
    ssd: SsdSearch,
    last: Option<FeatureEvent>,
    placement: Placement,
    /// Graph-cut placement's state (None for scan placement).
    graphcut: Option<GraphcutFeatures>,
}

impl FeatureSynthesis {
    /// Detects the exemplar's feature map (or takes `map`, e.g. one edited by hand) and those of
    /// the extra inputs.
    pub fn new(exemplar: &Image, map: Option<FeatureMap>, options: FeatureOptions) -> Result<Self> {
        let options = options.fitted(exemplar.width(), exemplar.height());
        options.validate(exemplar.width(), exemplar.height())?;
        // The inputs' images first, so that the budget is checked before any detection (over a
        // photo, detection and the indexes are most of the set-up's time and memory).
        let mut extras = Vec::new();
        for d in &options.extra_inputs {
            let image = d.apply(exemplar)?;
            if image.width() >= options.patch() && image.height() >= options.patch() {
                extras.push(image);
            }
        }
        let (w, h) = (options.output_width, options.output_height);
        // The budget is checked before anything of the output's size is allocated.
        let graphcut_options = GraphcutOptions {
            output_width: w,
            output_height: h,
            seed: options.seed,
            memory_budget_mib: options.memory_budget_mib,
            ..GraphcutOptions::default()
        };
        let graphcut_set = (options.placement == FeaturePlacement::Graphcut)
            .then(|| graphcut_estimate(exemplar, &graphcut_options))
            .transpose()?;
        let dims: Vec<(usize, usize)> = std::iter::once(exemplar)
            .chain(&extras)
            .map(|i| (i.width(), i.height()))
            .collect();
        working_set(&options, &dims, exemplar.channels(), graphcut_set.as_ref()).check(
            &format!("output {w}x{h}"),
            METHOD,
            options.memory_budget_mib,
        )?;
        let first_map = match map {
            Some(m) if (m.width, m.height) == (exemplar.width(), exemplar.height()) => m,
            Some(m) => {
                return Err(Error::InvalidSize {
                    what: "feature map",
                    width: m.width,
                    height: m.height,
                    reason: format!(
                        "must match the {}x{} exemplar",
                        exemplar.width(),
                        exemplar.height()
                    ),
                });
            }
            None => detect(exemplar, options.detect)?,
        };
        let mut maps = vec![first_map];
        for image in &extras {
            maps.push(detect(image, options.detect)?);
        }
        let mut inputs = Vec::new();
        let graphcut = if options.placement == FeaturePlacement::Graphcut {
            Some(GraphcutFeatures::new(
                exemplar,
                maps,
                extras,
                graphcut_options,
                HybridOptions {
                    feature_weight: options.feature_weight,
                    candidates: options.candidates(),
                    band: options.zone(),
                    seam_feature_weight: options.seam_feature_weight,
                },
            )?)
        } else {
            let images = std::iter::once(exemplar.clone()).chain(extras);
            for (image, map) in images.zip(maps) {
                inputs.push(Input {
                    index: FeatureIndex::new(&map),
                    map,
                    image,
                });
            }
            None
        };
        let step = options.patch() - options.zone();
        let ys = scan_origins(h, options.patch(), step);
        let xs = scan_origins(w, options.patch(), step);
        Ok(FeatureSynthesis {
            output: Image::new(w, h, exemplar.channels())?,
            filled: vec![false; w * h],
            feature: vec![false; w * h],
            angle: vec![0.0; w * h],
            origins: ys
                .iter()
                .flat_map(|&y| xs.iter().map(move |&x| (x, y)))
                .collect(),
            next: 0,
            rng: Rng::new(options.seed ^ 0x0fea_70e5),
            graph: Graph::new(1)?,
            ssd: SsdSearch::new(),
            last: None,
            placement: Placement::default(),
            input_dims: dims,
            graphcut,
            inputs,
            options,
        })
    }

    /// The estimated working set (see `super::memory`).
    #[must_use]
    pub fn working_set(&self) -> crate::core::budget::WorkingSet {
        let graphcut = self
            .graphcut
            .as_ref()
            .map(|g| g.session.synthesis().working_set());
        working_set(
            &self.options,
            &self.input_dims,
            self.output.channels(),
            graphcut.as_ref(),
        )
    }

    /// Whether the output is finished: every scan position filled, or graph-cut placement done.
    #[must_use]
    pub fn is_done(&self) -> bool {
        match &self.graphcut {
            Some(g) => g.session.is_done(),
            None => self.next >= self.origins.len(),
        }
    }

    /// The output as far as it is made.
    #[must_use]
    pub fn image(&self) -> &Image {
        match &self.graphcut {
            Some(g) => &g.session.synthesis().canvas.pixels,
            None => &self.output,
        }
    }

    /// The synthesised feature map so far.
    #[must_use]
    pub fn feature_mask(&self) -> &[bool] {
        &self.feature
    }

    /// The tangent angle at every output pixel (meaningful where the feature mask is set).
    #[must_use]
    pub fn feature_angles(&self) -> &[f32] {
        &self.angle
    }

    /// The exemplar's feature map (as detected or given).
    #[must_use]
    pub fn exemplar_map(&self) -> &FeatureMap {
        match &self.graphcut {
            Some(g) => &g.features[0].map,
            None => &self.inputs[0].map,
        }
    }

    /// The last placement (its box, context region, correspondences, warp grid), for the views.
    #[must_use]
    pub fn placement(&self) -> &Placement {
        &self.placement
    }

    /// The options, with the default patch side fitted to the exemplar.
    #[must_use]
    pub fn options(&self) -> &FeatureOptions {
        &self.options
    }

    /// Places the next patch.
    pub fn step(&mut self) -> Result<FeatureEvent> {
        if self.is_done() {
            let mut last = self.last.expect("a finished synthesis has stepped");
            last.done = true;
            return Ok(last);
        }
        let event = if self.graphcut.is_some() {
            self.place_graphcut()?
        } else {
            let (px, py) = self.origins[self.next];
            self.place(px, py)?
        };
        self.next += 1;
        let event = FeatureEvent {
            done: self.is_done(),
            ..event
        };
        self.last = Some(event);
        Ok(event)
    }

    /// The broken-feature count on the synthesised feature map (`broken::carried_broken`):
    /// curve ends per 1000 curve pixels above the exemplar map's.
    #[must_use]
    pub fn carried_broken(&self) -> f64 {
        let map = self.exemplar_map();
        super::broken::carried_broken(
            &self.feature,
            (self.output.width(), self.output.height()),
            &map.mask,
            (map.width, map.height),
        )
    }

    /// One step of graph-cut placement with the feature cost.
    /// The graph-cut session that places the patches (graph-cut placement only): its placement
    /// anatomy (cost surface, seam graph) is the page's view of a feature-guided placement.
    #[must_use]
    pub fn graphcut_session(&self) -> Option<&crate::methods::graphcut::Session> {
        self.graphcut.as_ref().map(|g| &g.session)
    }

    /// The same, mutable (to turn its anatomy on).
    pub fn graphcut_session_mut(&mut self) -> Option<&mut crate::methods::graphcut::Session> {
        self.graphcut.as_mut().map(|g| &mut g.session)
    }

    fn place_graphcut(&mut self) -> Result<FeatureEvent> {
        let g = self.graphcut.as_mut().expect("graph-cut placement");
        let e = g.step()?;
        update_canvas_features(
            g.session.synthesis(),
            &g.features,
            e.rect,
            &mut self.feature,
            &mut self.angle,
        );
        let (tx, ty, pw, ph) = e.rect;
        let choice = g.last;
        let (w, h) = (self.options.output_width, self.options.output_height);
        let (x, y) = (
            tx.clamp(0, w as i64) as usize,
            ty.clamp(0, h as i64) as usize,
        );
        self.placement = Placement {
            x,
            y,
            size: pw.min(ph).min(w - x).min(h - y),
            region: None,
            pairs: Vec::new(),
            grid: Vec::new(),
        };
        Ok(FeatureEvent {
            patch: self.next,
            patches: if e.done { self.next + 1 } else { self.next + 2 },
            x,
            y,
            input: e.patch.map_or(0, |p| p.source as usize),
            source_x: (-tx).max(0) as usize,
            source_y: (-ty).max(0) as usize,
            feature_cost: choice.map_or(0.0, |c| c.feature_cost),
            colour_cost: choice.map_or(0.0, |c| c.colour_cost),
            context_features: choice.map_or(0, |c| c.context_features),
            correspondences: 0,
            warp: WarpKind::Unavailable,
            colour_only: choice.is_some_and(|c| c.colour_only),
            done: false,
        })
    }

    fn place(&mut self, px: usize, py: usize) -> Result<FeatureEvent> {
        let p = self.options.patch();
        let (w, h) = (self.options.output_width, self.options.output_height);
        let c = self.output.channels();
        let at = |x: usize, y: usize| (py + y) * w + px + x;
        let scan = ScanWindow {
            filled: &self.filled,
            output_width: w,
            output_height: h,
            x: px,
            y: py,
            size: p,
        };
        let made = scan.made();
        // The context region's shape: full made rows at the top, then made columns at the left.
        let top = (0..p)
            .take_while(|&y| (0..p).all(|x| made[y * p + x]))
            .count();
        let left = if top < p {
            (0..p)
                .take_while(|&x| (top..p).all(|y| made[y * p + x]))
                .count()
        } else {
            0
        };
        let region = Region { size: p, top, left };
        let context: Vec<ContextFeature> = (0..p * p)
            .filter(|&i| made[i] && region.contains(i % p, i / p) && self.feature[at(i % p, i / p)])
            .map(|i| ContextFeature {
                x: i % p,
                y: i / p,
                angle: self.angle[at(i % p, i / p)],
            })
            .collect();
        let any_made = made.iter().any(|&m| m);
        // Score every candidate of every input.
        let window = Image::from_fn(p, p, c, |x, y, k| self.output.pixel(px + x, py + y)[k])?;
        let weights: Vec<f32> = made.iter().map(|&m| f32::from(u8::from(m))).collect();
        let mut candidates: Vec<(usize, usize, usize, f32, f32)> = Vec::new();
        for (k, input) in self.inputs.iter().enumerate() {
            let (iw, ih) = (input.image.width(), input.image.height());
            let colour = if any_made {
                Some(self.ssd.search(
                    &input.image,
                    None,
                    &window,
                    Some(&weights),
                    Boundary::Open,
                )?)
            } else {
                None
            };
            for ty in 0..=ih - p {
                for tx in 0..=iw - p {
                    let colour_cost = colour.as_ref().map_or(0.0, |m| {
                        let (cost, area) = m.get(tx as isize, ty as isize).unwrap_or((0.0, 1.0));
                        (cost / (area.max(1.0) * c as f32)).max(0.0)
                    });
                    candidates.push((k, tx, ty, 0.0, colour_cost));
                }
            }
        }
        // The feature cost of the best candidates by colour.
        if any_made {
            let keep = self.options.candidates().min(candidates.len());
            candidates.select_nth_unstable_by(keep - 1, |a, b| a.4.total_cmp(&b.4));
            candidates.truncate(keep);
            for cand in &mut candidates {
                cand.3 = self.inputs[cand.0].index.cost(
                    &context,
                    region,
                    cand.1,
                    cand.2,
                    TAU_MATCH,
                    p as f32 / 2.0,
                );
            }
        }
        let mean = |f: fn(&(usize, usize, usize, f32, f32)) -> f32| {
            candidates.iter().map(|c| f64::from(f(c))).sum::<f64>() as f32 / candidates.len() as f32
        };
        let (mean_feature, mean_colour) = (mean(|c| c.3), mean(|c| c.4));
        let colour_only = any_made
            && (self.inputs.iter().all(|i| i.index.features() == 0) || mean_feature <= 0.0);
        let wf = if colour_only {
            0.0
        } else {
            self.options.feature_weight
        };
        let total = |c: &(usize, usize, usize, f32, f32)| {
            let f = if mean_feature > 0.0 {
                c.3 / mean_feature
            } else {
                0.0
            };
            let s = if mean_colour > 0.0 {
                c.4 / mean_colour
            } else {
                0.0
            };
            wf * f + (1.0 - wf) * s
        };
        let best = candidates.iter().map(total).fold(f32::INFINITY, f32::min);
        let limit = best * (1.0 + self.options.tolerance) + 1e-9;
        let acceptable: Vec<usize> = (0..candidates.len())
            .filter(|&i| total(&candidates[i]) <= limit)
            .collect();
        let (input, tx, ty, feature_cost, colour_cost) =
            candidates[acceptable[self.rng.index(acceptable.len())]];
        // Bend the patch onto the context's features.
        let alignment = if self.options.warp && !context.is_empty() {
            Some(align(&self.inputs[input].index, &context, region, tx, ty))
        } else {
            None
        };
        let source = &self.inputs[input];
        let (iw, ih) = (source.image.width(), source.image.height());
        let mut new = vec![0.0f32; p * p * c];
        let mut new_feature = vec![false; p * p];
        let mut new_angle = vec![0.0f32; p * p];
        let mut px_buf = [0.0f32; 4];
        for i in 0..p * p {
            let (x, y) = (i % p, i / p);
            let (dx, dy) = alignment.as_ref().map_or((0.0, 0.0), |a| a.displacement[i]);
            let (sx, sy) = ((tx + x) as f32 + dx, (ty + y) as f32 + dy);
            // Whole-pixel moves: interpolating at fractional positions would soften thin curves
            // (a one-pixel grout line loses half its contrast at a half-pixel shift), which is
            // the very feature the warp is meant to join. The displacement changes slowly, so
            // rounding it gives a staircase of at most one pixel per step.
            let (rx, ry) = (sx.round(), sy.round());
            sample_bicubic(&source.image, rx, ry, Edge::Clamp, &mut px_buf);
            new[i * c..(i + 1) * c].copy_from_slice(&px_buf[..c]);
            let (nx, ny) = (
                rx.clamp(0.0, (iw - 1) as f32) as usize,
                ry.clamp(0.0, (ih - 1) as f32) as usize,
            );
            new_feature[i] = source.map.mask[ny * iw + nx];
            new_angle[i] = source.map.angle[ny * iw + nx];
        }
        // Merge along the minimum-cut seam.
        let old: Vec<f32> = (0..p)
            .flat_map(|y| {
                self.output.data()[at(0, y) * c..(at(0, y) + p) * c]
                    .iter()
                    .copied()
            })
            .collect();
        let keep = scan.keep_old(&mut self.graph, c, &old, &new)?;
        for i in (0..p * p).filter(|&i| !keep[i]) {
            let (x, y) = (i % p, i / p);
            self.output
                .pixel_mut(px + x, py + y)
                .copy_from_slice(&new[i * c..(i + 1) * c]);
            let o = at(x, y);
            self.filled[o] = true;
            self.feature[o] = new_feature[i];
            self.angle[o] = new_angle[i];
        }
        let kind = alignment.as_ref().map_or(WarpKind::None, |a| a.kind);
        let iw0 = self.inputs[input].image.width();
        self.placement = Placement {
            x: px,
            y: py,
            size: p,
            region: any_made.then_some(region),
            pairs: alignment.as_ref().map_or_else(Vec::new, |a| {
                a.correspondences
                    .iter()
                    .map(|cr| {
                        let f = context[cr.context];
                        let (jx, jy) = (
                            (cr.target % iw0) as f32 - tx as f32,
                            (cr.target / iw0) as f32 - ty as f32,
                        );
                        (
                            ((px + f.x) as f32, (py + f.y) as f32),
                            (px as f32 + jx, py as f32 + jy),
                        )
                    })
                    .collect()
            }),
            grid: (0..p)
                .step_by(4)
                .flat_map(|y| (0..p).step_by(4).map(move |x| (x, y)))
                .map(|(x, y)| {
                    alignment
                        .as_ref()
                        .map_or((0.0, 0.0), |a| a.displacement[y * p + x])
                })
                .collect(),
        };
        Ok(FeatureEvent {
            patch: self.next,
            patches: self.origins.len(),
            x: px,
            y: py,
            input,
            source_x: tx,
            source_y: ty,
            feature_cost,
            colour_cost,
            context_features: context.len(),
            correspondences: alignment.as_ref().map_or(0, |a| a.correspondences.len()),
            warp: kind,
            colour_only,
            done: false,
        })
    }
}
#[cfg(test)]
#[path = "session_tests.rs"]
mod tests;
