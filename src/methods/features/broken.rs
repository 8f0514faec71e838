//! The broken-feature count: curve ends per 1000 curve pixels in the feature map detected on an
//! output, minus the same figure for the exemplar's own map. A curve cut by a patch seam ends
//! where it should go on, so broken features raise it; the exemplar's own ends (a crop's border,
//! real line ends) are taken off. Lower is better; 0 means no more ends than the exemplar has.
//! Both maps are detected the same way, with the exemplar's absolute threshold, so the figure
//! judges the pictures, whichever method made them.

use super::detect::{DetectOptions, FeatureMap, detect, detect_with_threshold};
use super::thinning::endpoints;
use crate::core::{Image, Result};

/// Curve ends per 1000 curve pixels (0 for a map without curves).
#[must_use]
pub fn ends_per_thousand(mask: &[bool], width: usize, height: usize) -> f64 {
    let pixels = mask.iter().filter(|&&m| m).count();
    if pixels == 0 {
        return 0.0;
    }
    1000.0 * endpoints(mask, width, height) as f64 / pixels as f64
}

/// What the count needs of the exemplar: how its map was detected (the absolute threshold
/// included, so that outputs are detected the same way) and its own curve ends. Kept apart from
/// the map so that a map edited by hand still scores outputs against the exemplar as detected.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BrokenBaseline {
    options: DetectOptions,
    threshold: f32,
    ends_per_thousand: f64,
}

impl BrokenBaseline {
    /// The baseline of `own`, the exemplar's map as `detect(exemplar, options)` gave it.
    #[must_use]
    pub fn of(own: &FeatureMap, options: DetectOptions) -> BrokenBaseline {
        BrokenBaseline {
            options,
            threshold: own.threshold,
            ends_per_thousand: ends_per_thousand(&own.mask, own.width, own.height),
        }
    }

    /// The broken-feature count of `output`.
    #[must_use]
    pub fn broken(&self, output: &Image) -> f64 {
        let o = self.options;
        let theirs = detect_with_threshold(output, o.kind, self.threshold, o.alpha);
        ends_per_thousand(&theirs.mask, output.width(), output.height()) - self.ends_per_thousand
    }
}

/// The broken-feature count on a carried map: curve ends per 1000 curve pixels of `carried` (an
/// output's synthesised feature map, `width` x `height`: every pixel carries the curve of the
/// source pixel it shows) minus those of `source`, the mask it carried. It holds only the source's
/// curves, so its ends are curves that seams cut (and the output's border), not what a detector
/// finds in the output's pixels (grain, blur).
#[must_use]
pub fn carried_broken(
    carried: &[bool],
    (width, height): (usize, usize),
    source: &[bool],
    (source_width, source_height): (usize, usize),
) -> f64 {
    ends_per_thousand(carried, width, height)
        - ends_per_thousand(source, source_width, source_height)
}

/// The broken-feature count of `output` against `exemplar`.
pub fn broken_features(exemplar: &Image, output: &Image, options: DetectOptions) -> Result<f64> {
    let own = detect(exemplar, options)?;
    Ok(BrokenBaseline::of(&own, options).broken(output))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_carried_map_counts_the_curves_seams_cut() {
        // The source: three whole horizontal lines. Carried whole, the count is the border's
        // alone (0 when output and source are the same); carried with one line cut, two more ends.
        let (w, h) = (40, 24);
        let source = FeatureMap {
            width: w,
            height: h,
            mask: (0..w * h).map(|i| (i / w) % 8 == 4).collect(),
            angle: vec![0.0; w * h],
            response: vec![1.0; w * h],
            threshold: 0.5,
        };
        assert_eq!(
            carried_broken(&source.mask, (w, h), &source.mask, (w, h)),
            0.0
        );
        let mut cut = source.mask.clone();
        cut[12 * w + 20] = false;
        let curve_pixels = 3.0 * w as f64 - 1.0;
        let expected = 1000.0 * 8.0 / curve_pixels - 1000.0 * 6.0 / (3.0 * w as f64);
        assert!((carried_broken(&cut, (w, h), &source.mask, (w, h)) - expected).abs() < 1e-9);
    }

    #[test]
    fn broken_lines_count_more_ends_than_whole_ones() {
        let grid = |broken: bool| {
            Image::from_fn(64, 64, 1, move |x, y, _| {
                let line = (y % 16 == 8 && !(broken && (2..8).contains(&(x % 16)))) || x % 16 == 12;
                if line { 0.2 } else { 0.8 }
            })
            .unwrap()
        };
        let exemplar = grid(false);
        let whole = broken_features(&exemplar, &grid(false), DetectOptions::default()).unwrap();
        let broken = broken_features(&exemplar, &grid(true), DetectOptions::default()).unwrap();
        assert!(whole.abs() < 1e-9, "the exemplar against itself: {whole}");
        assert!(
            broken > 20.0,
            "every horizontal line cut four times by 6-pixel gaps: {broken}"
        );
    }
}
