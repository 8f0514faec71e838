//! Feature-guided placement for graph-cut textures: the paper's feature cost (eq. 2) joins the
//! colour SSD of graph cut's entire-patch matching. Each step is graph cut's (Kwatra et al.
//! 2003): an error region, every unused offset of the whole exemplar that covers it, the
//! area-normalised SSD of each against the made output; then, for the best candidates by colour,
//! eq. 2 between the output's features under the patch (the synthesised feature map: every made
//! pixel shows a source pixel, whose feature it carries) and the exemplar's. The two costs are
//! summed with the feature weight (each divided by its mean over the candidates, as in the
//! scan-order synthesis), expressed in SSD units, and the offset is drawn by graph cut's eq. 3;
//! the patch is merged with graph cut's seam memory and refinement patches.

use super::carried::SourceFeatures;
use super::carried::canvas_feature;
use super::detect::FeatureMap;
use super::matching::TAU_MATCH;
use crate::core::{Image, Result, math};
use crate::methods::graphcut::canvas::{Patch, UNCOVERED};
use crate::methods::graphcut::region::Candidate;
use crate::methods::graphcut::session::Drawn;
use crate::methods::graphcut::source::Source;
use crate::methods::graphcut::synthesis::Synthesis;
use crate::methods::graphcut::{Event, Options, Session};

/// What a feature-guided graph-cut placement chose.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Choice {
    pub patch: Patch,
    pub feature_cost: f32,
    pub colour_cost: f32,
    pub context_features: usize,
    pub colour_only: bool,
}

/// A rectangle of output pixels, `x0..x1` by `y0..y1`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Rect {
    pub x0: usize,
    pub y0: usize,
    pub x1: usize,
    pub y1: usize,
}

impl Rect {
    /// The output pixels `patch` lands on, clipped to the output (the part past the border of
    /// a wrapping output left out, as the feature cost leaves it).
    fn of_patch(s: &Synthesis, patch: Patch) -> Rect {
        let (pw, ph) = s.patch_extent(patch.source as usize);
        let clip = |v: i64, size: usize| v.clamp(0, size as i64) as usize;
        let (tx, ty) = (i64::from(patch.tx), i64::from(patch.ty));
        Rect {
            x0: clip(tx, s.canvas.width),
            y0: clip(ty, s.canvas.height),
            x1: clip(tx + pw as i64, s.canvas.width),
            y1: clip(ty + ph as i64, s.canvas.height),
        }
    }

    /// The smallest rectangle holding both.
    fn union(self, other: Rect) -> Rect {
        Rect {
            x0: self.x0.min(other.x0),
            y0: self.y0.min(other.y0),
            x1: self.x1.max(other.x1),
            y1: self.y1.max(other.y1),
        }
    }

    fn width(self) -> usize {
        self.x1 - self.x0
    }

    fn pixels(self) -> impl Iterator<Item = (usize, usize)> {
        (self.y0..self.y1).flat_map(move |y| (self.x0..self.x1).map(move |x| (x, y)))
    }
}

/// Where the next patch meets the made output: made pixels within `band` pixels (Chebyshev) of
/// an unmade one while the output is not covered, and the error region once it is. This is the
/// context of the feature cost, as the L-shaped overlap is for scan-order patches: the seam runs
/// there, so that is where features must continue. Over the whole output.
#[must_use]
pub fn frontier(s: &Synthesis, band: usize) -> Vec<bool> {
    let whole = Rect {
        x0: 0,
        y0: 0,
        x1: s.canvas.width,
        y1: s.canvas.height,
    };
    frontier_in(s, band, whole)
}

/// [`frontier`] over the pixels of `rect` only (row by row), looking `band` pixels around it:
/// the same values, at a cost that grows with the rectangle rather than the output.
#[must_use]
pub fn frontier_in(s: &Synthesis, band: usize, rect: Rect) -> Vec<bool> {
    let (w, h) = (s.canvas.width, s.canvas.height);
    if s.canvas.is_covered() {
        let r = s.error_region();
        return rect
            .pixels()
            .map(|(x, y)| {
                crate::methods::graphcut::region::region_contains(r, x, y, w, h, s.canvas.wrap)
            })
            .collect();
    }
    // Distance to the nearest unmade pixel by two separable running minima (Chebyshev), over
    // the rectangle grown by the band (an unmade pixel further out is too far to count).
    let grown = Rect {
        x0: rect.x0.saturating_sub(band),
        y0: rect.y0.saturating_sub(band),
        x1: (rect.x1 + band).min(w),
        y1: (rect.y1 + band).min(h),
    };
    let (gw, gh) = (grown.width(), grown.y1 - grown.y0);
    let unmade: Vec<bool> = grown
        .pixels()
        .map(|(x, y)| s.canvas.label[y * w + x] == UNCOVERED)
        .collect();
    let dilate = |m: &[bool], along_rows: bool| -> Vec<bool> {
        let mut out = vec![false; gw * gh];
        let (len, lines) = if along_rows { (gw, gh) } else { (gh, gw) };
        for line in 0..lines {
            let at = |k: usize| {
                if along_rows {
                    line * gw + k
                } else {
                    k * gw + line
                }
            };
            let mut last: Option<usize> = None;
            for k in 0..len {
                if m[at(k)] {
                    last = Some(k);
                }
                out[at(k)] = last.is_some_and(|l| k - l <= band);
            }
            let mut next: Option<usize> = None;
            for k in (0..len).rev() {
                if m[at(k)] {
                    next = Some(k);
                }
                out[at(k)] |= next.is_some_and(|n| n - k <= band);
            }
        }
        out
    };
    let near = dilate(&dilate(&unmade, true), false);
    rect.pixels()
        .map(|(x, y)| {
            let g = (y - grown.y0) * gw + (x - grown.x0);
            near[g] && !unmade[g]
        })
        .collect()
}

/// Scores the candidates of one graph-cut step by colour SSD plus feature cost and draws one
/// (eq. 3 of graph-cut textures on the combined cost). `keep` candidates, the best by colour,
/// get the feature cost; the rest are dropped. Also returns the candidates drawn from with their
/// combined costs, where they are not `scored` itself.
pub fn choose(
    s: &mut Synthesis,
    features: &mut [SourceFeatures],
    scored: &[Candidate],
    feature_weight: f32,
    keep: usize,
    band: usize,
) -> Option<(Choice, Option<Vec<Candidate>>)> {
    if scored.is_empty() {
        return None;
    }
    let (w, h) = (s.canvas.width, s.canvas.height);
    if s.canvas.covered == 0 {
        let patch = s.choose(scored)?;
        let choice = Choice {
            patch,
            feature_cost: 0.0,
            colour_cost: 0.0,
            context_features: 0,
            colour_only: false,
        };
        return Some((choice, None));
    }
    let mut best: Vec<Candidate> = scored
        .iter()
        .copied()
        .filter(|c| c.cost.is_finite())
        .collect();
    if best.is_empty() {
        let choice = |patch| Choice {
            patch,
            feature_cost: 0.0,
            colour_cost: 0.0,
            context_features: 0,
            colour_only: true,
        };
        return s.choose(scored).map(|patch| (choice(patch), None));
    }
    let keep = keep.clamp(1, best.len());
    best.select_nth_unstable_by(keep - 1, |a, b| a.cost.total_cmp(&b.cost));
    best.truncate(keep);
    // The context: the output's feature pixels on the frontier under any kept candidate, in
    // scan order (with their tangents), found within the candidates' bounds only.
    let bounds = best
        .iter()
        .map(|c| Rect::of_patch(s, c.patch))
        .reduce(Rect::union)
        .expect("a candidate is kept");
    let near = frontier_in(s, band, bounds);
    let made_features: Vec<(usize, f32)> = bounds
        .pixels()
        .zip(near)
        .filter(|&(_, near)| near)
        .filter_map(|((x, y), _)| {
            let i = y * w + x;
            let (feature, angle) = canvas_feature(s, features, i);
            feature.then_some((i, angle))
        })
        .collect();
    let label = &s.canvas.label;
    let mut context: Vec<(usize, usize, f32)> = Vec::new();
    let mut costs: Vec<(f32, usize)> = Vec::with_capacity(best.len());
    for c in &best {
        let src = c.patch.source as usize;
        // The patch is the source's window (the whole source within the bound): window pixel
        // (u, v) is source pixel window + (u, v) and lands on output pixel t + (u, v).
        let sw = s.sources[src].width();
        let (pw, ph) = s.patch_extent(src);
        let (ew, eh) = s.window_extent(src);
        let (wx, wy) = (i64::from(c.patch.window.0), i64::from(c.patch.window.1));
        let (tx, ty) = (i64::from(c.patch.tx), i64::from(c.patch.ty));
        // The output's features under the patch, at the source pixels the patch shows there.
        context.clear();
        for &(i, angle) in &made_features {
            let (u, v) = ((i % w) as i64 - tx, (i / w) as i64 - ty);
            if (0..pw as i64).contains(&u) && (0..ph as i64).contains(&v) {
                context.push(((u + wx) as usize, (v + wy) as usize, angle));
            }
        }
        // The source's features that would land on made output pixels.
        let made_at = |j: usize| {
            let (u, v) = ((j % sw) as i64 - wx, (j / sw) as i64 - wy);
            let (ox, oy) = (u + tx, v + ty);
            (0..pw as i64).contains(&u)
                && (0..ph as i64).contains(&v)
                && (0..w as i64).contains(&ox)
                && (0..h as i64).contains(&oy)
                && label[oy as usize * w + ox as usize] != UNCOVERED
        };
        let f = &mut features[src];
        // Only the window's rows can land on the output (the pixels are in scan order).
        let rows = |v: i64| f.pixels.partition_point(|&j| j < (v as usize) * sw);
        let in_rows = &f.pixels[rows(wy)..rows(wy + ph as i64)];
        let overlap = in_rows.iter().filter(|&&j| made_at(j)).count() as u32;
        let cost = f.index.cost_in_exemplar(
            &context,
            overlap,
            made_at,
            TAU_MATCH,
            ew.min(eh) as f32 / 4.0,
        );
        costs.push((cost, context.len()));
    }
    let mean = |v: &mut dyn Iterator<Item = f32>| {
        let (sum, n) = v.fold((0.0f64, 0usize), |(s, n), x| (s + f64::from(x), n + 1));
        (sum / n.max(1) as f64) as f32
    };
    let mean_colour = mean(&mut best.iter().map(|c| c.cost));
    let mean_feature = mean(&mut costs.iter().map(|c| c.0));
    let colour_only = mean_feature <= 0.0 || features.iter().all(|f| f.pixels.is_empty());
    // The feature cost in SSD units: at weight 0.5 a candidate at the mean feature cost pays the
    // mean colour cost again; weight 0 is graph cut's own choice, weight 1 features alone.
    let (wc, wf) = if colour_only {
        (1.0, 0.0)
    } else {
        (
            (2.0 * (1.0 - feature_weight)).min(1.0),
            (2.0 * feature_weight).min(1.0) * mean_colour.max(1e-12) / mean_feature,
        )
    };
    let combined: Vec<Candidate> = best
        .iter()
        .zip(&costs)
        .map(|(c, f)| Candidate {
            patch: c.patch,
            cost: wc * c.cost + wf * f.0,
        })
        .collect();
    let patch = s.choose(&combined)?;
    let k = best.iter().position(|c| c.patch == patch)?;
    let choice = Choice {
        patch,
        feature_cost: costs[k].0,
        colour_cost: best[k].cost,
        context_features: costs[k].1,
        colour_only,
    };
    Some((choice, Some(combined)))
}

/// The feature-guided choices of graph-cut placement.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HybridOptions {
    /// Weight of the feature cost against the colour SSD (0.5: alike).
    pub feature_weight: f32,
    /// Candidates, the best by colour, whose feature cost is computed.
    pub candidates: usize,
    /// Width of the frontier band whose features make the context.
    pub band: usize,
    /// Seam cost per pixel where the two patches disagree on a feature.
    pub seam_feature_weight: f32,
}

/// The colour step a feature makes in `image`: the mean over its feature pixels of the largest
/// colour distance among the pixel and the pixels two steps to either side across the curve
/// (along the normal of the tangent): an edge's step, a ridge's (a line's) contrast with its
/// sides. 1 where there are no features.
#[must_use]
pub fn feature_step(image: &Image, map: &FeatureMap) -> f32 {
    let (w, h) = (image.width() as f32, image.height() as f32);
    let (mut sum, mut n) = (0.0f64, 0usize);
    for (i, _) in map.mask.iter().enumerate().filter(|(_, m)| **m) {
        let (x, y) = ((i % map.width) as f32, (i / map.width) as f32);
        let (nx, ny) = (
            -math::sinf(map.angle[i]) * 2.0,
            math::cosf(map.angle[i]) * 2.0,
        );
        let at = |dx: f32, dy: f32| {
            let (px, py) = ((x + dx).round(), (y + dy).round());
            ((0.0..w).contains(&px) && (0.0..h).contains(&py))
                .then(|| image.pixel(px as usize, py as usize))
        };
        if let (Some(a), Some(b), Some(c)) = (at(nx, ny), at(-nx, -ny), at(0.0, 0.0)) {
            use crate::methods::graphcut::cost::colour_distance as d;
            sum += f64::from(d(a, b).max(d(a, c)).max(d(b, c)));
            n += 1;
        }
    }
    if n == 0 { 1.0 } else { (sum / n as f64) as f32 }
}

/// A graph-cut synthesis whose offsets are chosen with the feature cost.
pub struct GraphcutFeatures {
    pub session: Session,
    pub features: Vec<SourceFeatures>,
    pub options: HybridOptions,
    /// The last step's choice.
    pub last: Option<Choice>,
}

impl GraphcutFeatures {
    /// `maps`: the feature map of every source, the exemplar's first; `extra`: the images of the
    /// sources after the exemplar (extra inputs).
    pub fn new(
        exemplar: &Image,
        maps: Vec<FeatureMap>,
        extra: Vec<Image>,
        options: Options,
        hybrid: HybridOptions,
    ) -> Result<GraphcutFeatures> {
        let mut synthesis = Synthesis::new(exemplar, options)?;
        for (k, image) in extra.into_iter().enumerate() {
            synthesis
                .sources
                .push(Source::new(image, 1.0, format!("input {}", k + 1)));
        }
        synthesis.seam_features = maps.iter().map(|m| m.mask.clone()).collect();
        // The weight is in units of the exemplar's own feature contrast, so that breaking a
        // feature at a seam costs what cutting across it visibly would: an absolute unit
        // (1 = a black-to-white step) made the seams of low-contrast textures (paving's cracks,
        // carpet, tiles) dodge features at any colour cost, 14-16% worse coherence than plain
        // graph cut over seeds 1-3; in this unit 0.74-1.08x of it, with fewer broken features
        // than graph cut on all six structured samples.
        let unit = maps.first().map_or(1.0, |m| feature_step(exemplar, m));
        synthesis.seam_feature_weight = hybrid.seam_feature_weight * unit;
        Ok(GraphcutFeatures {
            session: Session::from_synthesis(synthesis),
            features: maps.into_iter().map(SourceFeatures::new).collect(),
            options: hybrid,
            last: None,
        })
    }

    /// Places one patch (graph cut's step with the feature-guided choice).
    pub fn step(&mut self) -> Result<Event> {
        let features = &mut self.features;
        let o = self.options;
        let mut last = None;
        let event = self.session.step_with(|s, scored| {
            let (c, pool) = choose(s, features, scored, o.feature_weight, o.candidates, o.band)?;
            last = Some(c);
            Some(Drawn {
                patch: c.patch,
                pool,
            })
        })?;
        self.last = last;
        Ok(event)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::testing::sample;
    use crate::methods::features::detect::{DetectOptions, detect};
    use crate::methods::features::matching::{ContextFeature, FeatureIndex, Region};

    /// A map with one curve: column `x` from top to bottom, tangent vertical.
    fn vertical_curve(w: usize, h: usize, x: usize) -> FeatureMap {
        let mut mask = vec![false; w * h];
        for y in 0..h {
            mask[y * w + x] = true;
        }
        FeatureMap {
            width: w,
            height: h,
            mask,
            angle: vec![std::f32::consts::FRAC_PI_2; w * h],
            response: vec![1.0; w * h],
            threshold: 0.5,
        }
    }

    #[test]
    fn feature_step_is_an_edges_step_and_a_lines_contrast() {
        let (w, h) = (16, 8);
        // An edge from grey 0.2 to 0.7 at column 8: the step is 0.5 per channel, sqrt(3) * 0.5
        // as a colour distance.
        let edge = Image::from_fn(w, h, 3, |x, _, _| if x < 8 { 0.2 } else { 0.7 }).unwrap();
        let step = feature_step(&edge, &vertical_curve(w, h, 8));
        assert!((step - 0.5 * 3f32.sqrt()).abs() < 1e-5, "{step}");
        // A dark line (0.1) on 0.4: the line against its sides, 0.3 per channel.
        let line = Image::from_fn(w, h, 3, |x, _, _| if x == 5 { 0.1 } else { 0.4 }).unwrap();
        let step = feature_step(&line, &vertical_curve(w, h, 5));
        assert!((step - 0.3 * 3f32.sqrt()).abs() < 1e-5, "{step}");
        // No features: the absolute unit.
        let none = FeatureMap {
            mask: vec![false; w * h],
            ..vertical_curve(w, h, 5)
        };
        assert_eq!(feature_step(&line, &none), 1.0);
        // A curve at the border has no pixel beyond it: it is left out.
        let border = feature_step(&edge, &vertical_curve(w, h, 0));
        assert_eq!(border, 1.0);
    }

    #[test]
    fn eq2_in_exemplar_coordinates_equals_the_l_shaped_cost() {
        let ex = sample("tiles_64");
        let map = detect(&ex, DetectOptions::default()).unwrap();
        let mut index = FeatureIndex::new(&map);
        let region = Region {
            size: 24,
            top: 6,
            left: 6,
        };
        // The context: the features of the exemplar's own L at (20, 12), shifted by one pixel.
        let context: Vec<ContextFeature> = (0..24 * 24)
            .map(|i| (i % 24, i / 24))
            .filter(|&(x, y)| region.contains(x, y) && map.mask[(13 + y) * 64 + 21 + x])
            .map(|(x, y)| ContextFeature {
                x,
                y,
                angle: map.angle[(13 + y) * 64 + 21 + x],
            })
            .collect();
        assert!(context.len() > 5);
        let (tx, ty) = (20, 12);
        let l = index.cost(&context, region, tx, ty, TAU_MATCH, 12.0);
        let points: Vec<(usize, usize, f32)> = context
            .iter()
            .map(|f| (tx + f.x, ty + f.y, f.angle))
            .collect();
        let inside = |j: usize| {
            let (x, y) = (j % 64, j / 64);
            x >= tx && y >= ty && region.contains(x - tx, y - ty)
        };
        let n = (0..64 * 64).filter(|&j| map.mask[j] && inside(j)).count() as u32;
        let e = index.cost_in_exemplar(&points, n, inside, TAU_MATCH, 12.0);
        assert!((l - e).abs() < 1e-6, "{l} {e}");
        assert!(l > 0.0);
    }

    #[test]
    fn the_frontier_is_the_made_band_next_to_unmade_pixels() {
        let ex = sample("tiles_64");
        let mut s = Synthesis::new(
            &ex,
            Options {
                output_width: 96,
                output_height: 80,
                ..Options::default()
            },
        )
        .unwrap();
        s.place(Patch::new(0, 0, 0), &[], &[]).unwrap();
        let near = frontier(&s, 5);
        for y in 0..80 {
            for x in 0..96 {
                let made = x < 64 && y < 64;
                let close = made && (x + 5 >= 64 || y + 5 >= 64);
                assert_eq!(near[y * 96 + x], close, "({x}, {y})");
            }
        }
        // Over a part of the output: the same values, though the unmade pixels that make them
        // lie outside the part.
        for rect in [
            Rect {
                x0: 50,
                y0: 10,
                x1: 62,
                y1: 70,
            },
            Rect {
                x0: 0,
                y0: 55,
                x1: 96,
                y1: 60,
            },
            Rect {
                x0: 59,
                y0: 59,
                x1: 60,
                y1: 60,
            },
        ] {
            let part = frontier_in(&s, 5, rect);
            let expected: Vec<bool> = rect.pixels().map(|(x, y)| near[y * 96 + x]).collect();
            assert_eq!(part, expected, "{rect:?}");
        }
    }

    /// The placement anatomy of a feature-guided step shows what eq. 3 drew from: the best
    /// candidates by colour with their combined costs, not graph cut's draw over every offset.
    #[test]
    fn the_anatomy_draws_over_the_pool_feature_guided_placement_drew_from() {
        let ex = sample("tiles_64");
        let map = detect(&ex, DetectOptions::default()).unwrap();
        let options = Options {
            output_width: 112,
            output_height: 96,
            ..Options::default()
        };
        let hybrid = HybridOptions {
            feature_weight: 0.5,
            candidates: 12,
            band: 8,
            seam_feature_weight: 1.0,
        };
        let mut g = GraphcutFeatures::new(&ex, vec![map], Vec::new(), options, hybrid).unwrap();
        for _ in 0..2 {
            g.step().unwrap();
        }
        g.session.set_anatomy(true);
        g.step().unwrap();
        let choice = g.last.expect("a feature-guided choice");
        assert!(!choice.colour_only, "tiles have oriented features");
        let surface = g.session.placement_costs().expect("recorded");
        let finite = surface.cost.iter().filter(|c| c.is_finite()).count();
        let drawable = surface.probability.iter().filter(|&&p| p > 0.0).count();
        let total: f32 = surface.probability.iter().sum();
        assert!(finite > 12, "{finite} offsets scored");
        assert!((1..=12).contains(&drawable), "{drawable} offsets drawable");
        assert!((total - 1.0).abs() < 1e-4, "{total}");
        let (cx, cy) = surface.chosen.expect("marked");
        assert!(surface.probability[cy * surface.width + cx] > 0.0);
    }
}
