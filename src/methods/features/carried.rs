//! The synthesised feature map of a graph-cut canvas (Wu & Yu 2004, section 3: the texture and
//! its feature map grow together): every made output pixel carries the curve, and its tangent,
//! of the source pixel it shows. Feature-guided placement matches against it; the broken-feature
//! count at seams counts its curve ends, for feature-guided synthesis and plain graph cut alike.

use super::detect::FeatureMap;
use super::matching::FeatureIndex;
use crate::methods::graphcut::canvas::UNCOVERED;
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

/// The synthesised feature map of a graph-cut canvas: each made pixel carries the feature (and
/// tangent) of the source pixel it shows.
#[must_use]
pub fn canvas_features(s: &Synthesis, features: &[SourceFeatures]) -> (Vec<bool>, Vec<f32>) {
    let (w, h) = (s.canvas.width, s.canvas.height);
    let mut mask = vec![false; w * h];
    let mut angle = vec![0.0f32; w * h];
    for (i, (m, a)) in mask.iter_mut().zip(&mut angle).enumerate() {
        (*m, *a) = canvas_feature(s, features, i);
    }
    (mask, angle)
}

/// Brings `mask` and `angle` ([`canvas_features`]) up to date after a placement over `rect`
/// (x, y, width, height in output coordinates; reduced modulo the output on a wrapping canvas):
/// a placement relabels pixels of its own patch only, so a step costs the patch's area, not the
/// output's.
pub fn update_canvas_features(
    s: &Synthesis,
    features: &[SourceFeatures],
    rect: (i64, i64, usize, usize),
    mask: &mut [bool],
    angle: &mut [f32],
) {
    let (w, h) = (s.canvas.width as i64, s.canvas.height as i64);
    let (x, y, pw, ph) = rect;
    let axis = |p: i64, size: i64| {
        if s.canvas.wrap {
            Some(p.rem_euclid(size))
        } else {
            (0..size).contains(&p).then_some(p)
        }
    };
    for oy in (y..y + ph.min(h as usize) as i64).filter_map(|v| axis(v, h)) {
        for ox in (x..x + pw.min(w as usize) as i64).filter_map(|u| axis(u, w)) {
            let i = (oy * w + ox) as usize;
            (mask[i], angle[i]) = canvas_feature(s, features, i);
        }
    }
}

/// The source and source pixel (index in its row-major pixels) output pixel `i` shows; None
/// where unmade.
fn shown_pixel(s: &Synthesis, i: usize) -> Option<(usize, usize)> {
    let w = s.canvas.width;
    let label = s.canvas.label[i];
    if label == UNCOVERED {
        return None;
    }
    let patch = s.canvas.patches[label as usize];
    let source = patch.source as usize;
    let (sx, sy) = s.source_coords(patch, i % w, i / w)?;
    Some((source, sy * s.sources[source].width() + sx))
}

/// The feature and tangent output pixel `i` shows (none where unmade).
pub(super) fn canvas_feature(s: &Synthesis, features: &[SourceFeatures], i: usize) -> (bool, f32) {
    shown_pixel(s, i).map_or((false, 0.0), |(source, j)| {
        let f = &features[source].map;
        (f.mask[j], f.angle[j])
    })
}

/// The carried feature map of a graph-cut canvas from the sources' curves alone: `masks[k]` is
/// source k's mask (row-major at its width), and a made pixel carries the curve of the source
/// pixel it shows. Sources past `masks` carry none.
#[must_use]
pub fn carried_mask(s: &Synthesis, masks: &[&[bool]]) -> Vec<bool> {
    (0..s.canvas.width * s.canvas.height)
        .map(|i| {
            shown_pixel(s, i)
                .is_some_and(|(source, j)| masks.get(source).is_some_and(|mask| mask[j]))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::testing::sample;
    use crate::methods::features::detect::{DetectOptions, detect};
    use crate::methods::graphcut::{Options, Session};

    #[test]
    fn the_carried_mask_is_the_canvas_feature_map() {
        let ex = sample("tiles_64");
        let map = detect(&ex, DetectOptions::default()).unwrap();
        let mut g = Session::new(
            &ex,
            Options {
                output_width: 96,
                output_height: 80,
                seed: 4,
                ..Options::default()
            },
        )
        .unwrap();
        while !g.step().unwrap().done {}
        let s = g.synthesis();
        let masks: [&[bool]; 1] = [&map.mask];
        let carried = carried_mask(s, &masks);
        let (oracle, _) = canvas_features(s, &[SourceFeatures::new(map.clone())]);
        assert_eq!(
            carried, oracle,
            "the mask alone carries what the full features do"
        );
        assert!(carried.iter().filter(|&&m| m).count() > 500);
        // A source without a mask carries nothing.
        assert!(carried_mask(s, &[]).iter().all(|&m| !m));
    }
}
