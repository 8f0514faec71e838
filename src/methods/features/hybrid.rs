//! Feature-guided placement for graph-cut textures: the paper's feature cost (eq. 2) joins the
//! colour SSD of graph cut's entire-patch matching. Each step is graph cut's (Kwatra et al.
//! 2003): an error region, every unused offset of the whole exemplar that covers it, the
//! area-normalised SSD of each against the made output; then, for the best candidates by colour,
//! eq. 2 between the output's features under the patch (the synthesised feature map: every made
//! pixel shows a source pixel, whose feature it carries) and the exemplar's. The two costs are
//! summed with the feature weight (each divided by its mean over the candidates, as in the
//! scan-order synthesis), expressed in SSD units, and the offset is drawn by graph cut's eq. 3;
//! the patch is merged with graph cut's seam memory and refinement patches.

use super::detect::FeatureMap;
use super::matching::{FeatureIndex, TAU_MATCH};
use crate::core::Result;
use crate::methods::graphcut::canvas::{Patch, UNCOVERED};
use crate::methods::graphcut::placement::Candidate;
use crate::methods::graphcut::synthesis::Synthesis;

/// One source of the synthesis with its features.
pub struct SourceFeatures {
    pub map: FeatureMap,
    pub index: FeatureIndex,
    /// Its feature pixels (y * width + x).
    pub pixels: Vec<usize>,
}

impl SourceFeatures {
    #[must_use]
    pub fn new(map: FeatureMap) -> SourceFeatures {
        SourceFeatures {
            index: FeatureIndex::new(&map),
            pixels: (0..map.mask.len()).filter(|&i| map.mask[i]).collect(),
            map,
        }
    }
}

/// What a feature-guided graph-cut placement chose.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Choice {
    pub patch: Patch,
    pub feature_cost: f32,
    pub colour_cost: f32,
    pub context_features: usize,
    pub colour_only: bool,
}

/// The synthesised feature map of a graph-cut canvas: each made pixel carries the feature (and
/// tangent) of the source pixel it shows.
#[must_use]
pub fn canvas_features(s: &Synthesis, features: &[SourceFeatures]) -> (Vec<bool>, Vec<f32>) {
    let (w, h) = (s.canvas.width, s.canvas.height);
    let mut mask = vec![false; w * h];
    let mut angle = vec![0.0f32; w * h];
    for i in 0..w * h {
        let label = s.canvas.label[i];
        if label == UNCOVERED {
            continue;
        }
        let patch = s.canvas.patches[label as usize];
        let source = &s.sources[patch.source as usize];
        if let Some((sx, sy)) = s.canvas.source_coords(patch, source, i % w, i / w) {
            let f = &features[patch.source as usize].map;
            let j = sy * f.width + sx;
            mask[i] = f.mask[j];
            angle[i] = f.angle[j];
        }
    }
    (mask, angle)
}

/// Where the next patch meets the made output: made pixels within `band` pixels (Chebyshev) of
/// an unmade one while the output is not covered, and the error region once it is. This is the
/// context of the feature cost, as the L-shaped overlap is for scan-order patches: the seam runs
/// there, so that is where features must continue.
#[must_use]
pub fn frontier(s: &Synthesis, band: usize) -> Vec<bool> {
    let (w, h) = (s.canvas.width, s.canvas.height);
    if s.canvas.is_covered() {
        let r = s.error_region();
        return (0..w * h)
            .map(|i| {
                crate::methods::graphcut::placement::region_contains(
                    r,
                    i % w,
                    i / w,
                    w,
                    h,
                    s.canvas.wrap,
                )
            })
            .collect();
    }
    // Distance to the nearest unmade pixel by two separable running minima (Chebyshev).
    let unmade: Vec<bool> = s.canvas.label.iter().map(|&l| l == UNCOVERED).collect();
    let dilate = |m: &[bool], along_rows: bool| -> Vec<bool> {
        let mut out = vec![false; w * h];
        let (len, lines) = if along_rows { (w, h) } else { (h, w) };
        for line in 0..lines {
            let at = |k: usize| {
                if along_rows {
                    line * w + k
                } else {
                    k * w + line
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
    (0..w * h).map(|i| near[i] && !unmade[i]).collect()
}

/// Scores the candidates of one graph-cut step by colour SSD plus feature cost and draws one
/// (eq. 3 of graph-cut textures on the combined cost). `keep` candidates, the best by colour,
/// get the feature cost; the rest are dropped.
pub fn choose(
    s: &mut Synthesis,
    features: &mut [SourceFeatures],
    scored: &[Candidate],
    feature_weight: f32,
    keep: usize,
    band: usize,
) -> Option<Choice> {
    if scored.is_empty() {
        return None;
    }
    let (w, h) = (s.canvas.width, s.canvas.height);
    if s.canvas.covered == 0 {
        let patch = s.choose(scored)?;
        return Some(Choice {
            patch,
            feature_cost: 0.0,
            colour_cost: 0.0,
            context_features: 0,
            colour_only: false,
        });
    }
    let (mask, angle) = canvas_features(s, features);
    let near = frontier(s, band);
    let made_features: Vec<usize> = (0..w * h).filter(|&i| mask[i] && near[i]).collect();
    let mut best: Vec<Candidate> = scored
        .iter()
        .copied()
        .filter(|c| c.cost.is_finite())
        .collect();
    if best.is_empty() {
        return s.choose(scored).map(|patch| Choice {
            patch,
            feature_cost: 0.0,
            colour_cost: 0.0,
            context_features: 0,
            colour_only: true,
        });
    }
    let keep = keep.clamp(1, best.len());
    best.select_nth_unstable_by(keep - 1, |a, b| a.cost.total_cmp(&b.cost));
    best.truncate(keep);
    let label = &s.canvas.label;
    let mut context: Vec<(usize, usize, f32)> = Vec::new();
    let mut costs: Vec<(f32, usize)> = Vec::with_capacity(best.len());
    for c in &best {
        let src = c.patch.source as usize;
        let (sw, sh) = (s.sources[src].width(), s.sources[src].height());
        let (tx, ty) = (i64::from(c.patch.tx), i64::from(c.patch.ty));
        // The output's features under the patch, at the source pixels the patch shows there.
        context.clear();
        for &i in &made_features {
            let (sx, sy) = ((i % w) as i64 - tx, (i / w) as i64 - ty);
            if (0..sw as i64).contains(&sx) && (0..sh as i64).contains(&sy) {
                context.push((sx as usize, sy as usize, angle[i]));
            }
        }
        // The source's features that would land on made output pixels.
        let made_at = |j: usize| {
            let (ox, oy) = ((j % sw) as i64 + tx, (j / sw) as i64 + ty);
            (0..w as i64).contains(&ox)
                && (0..h as i64).contains(&oy)
                && label[oy as usize * w + ox as usize] != UNCOVERED
        };
        let f = &mut features[src];
        let overlap = f.pixels.iter().filter(|&&j| made_at(j)).count() as u32;
        let cost = f.index.cost_in_exemplar(
            &context,
            overlap,
            made_at,
            TAU_MATCH,
            sw.min(sh) as f32 / 4.0,
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
    // The feature cost in SSD units: equal weights (0.5) make a candidate at the mean feature cost
    // pay the mean colour cost.
    let lambda = if colour_only || feature_weight >= 1.0 {
        0.0
    } else {
        feature_weight / (1.0 - feature_weight) * mean_colour.max(1e-12) / mean_feature
    };
    let combined: Vec<Candidate> = best
        .iter()
        .zip(&costs)
        .map(|(c, f)| Candidate {
            patch: c.patch,
            cost: c.cost + lambda * f.0,
        })
        .collect();
    let patch = s.choose(&combined)?;
    let k = best.iter().position(|c| c.patch == patch)?;
    Some(Choice {
        patch,
        feature_cost: costs[k].0,
        colour_cost: best[k].cost,
        context_features: costs[k].1,
        colour_only,
    })
}

/// A graph-cut synthesis whose offsets are chosen with the feature cost.
pub struct GraphcutFeatures {
    pub session: crate::methods::graphcut::Session,
    pub features: Vec<SourceFeatures>,
    pub feature_weight: f32,
    pub keep: usize,
    pub last: Option<Choice>,
}

impl GraphcutFeatures {
    /// `sources`: the images after the exemplar (extra inputs) with every source's feature map,
    /// the exemplar's first.
    pub fn new(
        exemplar: &crate::core::Image,
        maps: Vec<FeatureMap>,
        extra: Vec<crate::core::Image>,
        options: crate::methods::graphcut::Options,
        feature_weight: f32,
        keep: usize,
    ) -> Result<GraphcutFeatures> {
        let mut synthesis = Synthesis::new(exemplar, options)?;
        for (k, image) in extra.into_iter().enumerate() {
            synthesis
                .sources
                .push(crate::methods::graphcut::source::Source::new(
                    image,
                    1.0,
                    format!("input {}", k + 1),
                ));
        }
        synthesis.seam_features = maps.iter().map(|m| m.mask.clone()).collect();
        synthesis.seam_feature_weight = std::env::var("SEAMW").map_or(0.0, |v| v.parse().unwrap());
        Ok(GraphcutFeatures {
            session: crate::methods::graphcut::Session::from_synthesis(synthesis),
            features: maps.into_iter().map(SourceFeatures::new).collect(),
            feature_weight,
            keep,
            last: None,
        })
    }

    pub fn step(&mut self) -> Result<crate::methods::graphcut::Event> {
        let features = &mut self.features;
        let (wf, keep) = (self.feature_weight, self.keep);
        let band = std::env::var("BAND").map_or(16, |v| v.parse().unwrap());
        let mut last = None;
        let event = self.session.step_with(|s, scored| {
            let c = choose(s, features, scored, wf, keep, band)?;
            last = Some(c);
            Some(c.patch)
        })?;
        self.last = last;
        Ok(event)
    }
}
