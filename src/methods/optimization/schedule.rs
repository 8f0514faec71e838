//! The multi-level schedule (section 3.2) as plain data: decided first, printed and tested on its
//! own, then executed by the session.

use super::options::Options;
use crate::core::pyramid::half_size;
use crate::core::{Error, Result};

/// A neighbourhood of width `w` fits a level when the level's exemplar is at least
/// `FIT_RATIO * w` on its shorter side, leaving `(3w + 1)^2` or more neighbourhoods to choose
/// from. With a 128x128 exemplar and the default sizes this gives exactly the seven levels of
/// Fig. 3: random start, (1/4, 8), (1/2, 16), (1/2, 8), (1, 32), (1, 16), (1, 8).
pub const FIT_RATIO: usize = 4;

/// One synthesis level: a resolution and a neighbourhood size.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Level {
    /// Resolution index, 0 = full resolution, k = down-sampled k times.
    pub octave: usize,
    pub output_width: usize,
    pub output_height: usize,
    pub exemplar_width: usize,
    pub exemplar_height: usize,
    /// Neighbourhood width w.
    pub size: usize,
    /// Spacing of the neighbourhood grid X†: w / 4 (at least 1).
    pub spacing: usize,
}

/// The levels, coarsest first.
pub fn plan(
    exemplar_width: usize,
    exemplar_height: usize,
    options: &Options,
) -> Result<Vec<Level>> {
    let mut sizes = options.neighbourhood_sizes.clone();
    sizes.sort_unstable_by(|a, b| b.cmp(a));
    sizes.dedup();
    let dims_at = |octave: usize| {
        let mut d = (
            options.output_width,
            options.output_height,
            exemplar_width,
            exemplar_height,
        );
        for _ in 0..octave {
            d = (
                half_size(d.0),
                half_size(d.1),
                half_size(d.2),
                half_size(d.3),
            );
        }
        d
    };
    let level = |octave: usize, size: usize| {
        let (ow, oh, ew, eh) = dims_at(octave);
        Level {
            octave,
            output_width: ow,
            output_height: oh,
            exemplar_width: ew,
            exemplar_height: eh,
            size,
            spacing: (size / 4).max(1),
        }
    };
    let mut levels = Vec::new();
    for octave in (0..options.levels).rev() {
        let (ow, oh, ew, eh) = dims_at(octave);
        for &size in &sizes {
            if size * FIT_RATIO <= ew.min(eh) && size <= ow.min(oh) {
                levels.push(level(octave, size));
            }
        }
    }
    if levels.is_empty() {
        let (ow, oh, ew, eh) = dims_at(0);
        let Some(size) = fallback_size(&sizes, ew.min(eh), ow.min(oh)) else {
            return Err(Error::InvalidParameter {
                name: "neighbourhoodSizes",
                reason: format!(
                    "none of {:?} fits: a neighbourhood must be at most half the exemplar ({ew}x{eh}) and no larger than the output ({ow}x{oh})",
                    options.neighbourhood_sizes
                ),
            });
        };
        levels.push(level(0, size));
    }
    Ok(levels)
}

/// Where no size fits by [`FIT_RATIO`] (an exemplar of 16 to 31 pixels on its shorter side with
/// the default sizes): the smallest of `sizes` that is at most half the exemplar's shorter side
/// and no wider than the output's, used at full resolution only. Flow frames fall back the same
/// way, so an exemplar that texture optimisation takes animates too.
#[must_use]
pub fn fallback_size(sizes: &[usize], exemplar_side: usize, output_side: usize) -> Option<usize> {
    sizes
        .iter()
        .copied()
        .filter(|&s| 2 * s <= exemplar_side && s <= output_side)
        .min()
}

/// For every position `0..len` along one axis of the grid whose neighbourhoods start at
/// `corners` and are `size` wide: the index of the neighbourhood that holds the position with
/// its centre nearest (the first among equals), and the position's offset in it.
#[must_use]
pub fn nearest_nodes(corners: &[usize], len: usize, size: usize, wrap: bool) -> Vec<(usize, usize)> {
    (0..len)
        .map(|p| {
            let mut best = (usize::MAX, 0, 0);
            for (j, &c) in corners.iter().enumerate() {
                let offset = if wrap {
                    (p + len - c) % len
                } else {
                    p.wrapping_sub(c)
                };
                if offset < size {
                    let distance = offset.abs_diff(size / 2);
                    if distance < best.0 {
                        best = (distance, j, offset);
                    }
                }
            }
            (best.1, best.2)
        })
        .collect()
}

/// Positions (top-left corners, along one axis of length `len`) of the neighbourhood grid X†:
/// every `spacing` pixels from 0. Without wrapping, a last corner at `len - size` makes the grid
/// cover the border; with wrapping, corners run up to `len` and neighbourhoods wrap around.
#[must_use]
pub fn grid_axis(len: usize, size: usize, spacing: usize, wrap: bool) -> Vec<usize> {
    if wrap {
        return (0..len).step_by(spacing).collect();
    }
    let last = len - size;
    let mut axis: Vec<usize> = (0..=last).step_by(spacing).collect();
    if axis.last() != Some(&last) {
        axis.push(last);
    }
    axis
}

/// Index of the grid corner closest to `target` (ties to the first). Corners are sorted, so a
/// binary search finds the two around it: a scan per node made carrying matches into a
/// 1024x1024 level quadratic in the grid side (0.4 s at neighbourhood size 8).
#[must_use]
pub fn nearest_corner(corners: &[usize], target: f64) -> usize {
    let above = corners.partition_point(|&c| (c as f64) < target);
    match above {
        0 => 0,
        n if n == corners.len() => n - 1,
        n => {
            let (lo, hi) = (corners[n - 1] as f64, corners[n] as f64);
            if target - lo <= hi - target { n - 1 } else { n }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn summary(levels: &[Level]) -> Vec<(usize, usize)> {
        levels.iter().map(|l| (l.octave, l.size)).collect()
    }

    #[test]
    fn default_schedule_for_128_to_256_is_figure_3() {
        let levels = plan(128, 128, &Options::default()).unwrap();
        assert_eq!(
            summary(&levels),
            [(2, 8), (1, 16), (1, 8), (0, 32), (0, 16), (0, 8)]
        );
        assert_eq!(
            (
                levels[0].output_width,
                levels[0].exemplar_width,
                levels[0].spacing
            ),
            (64, 32, 2)
        );
        assert_eq!(levels[3].spacing, 8);
    }

    #[test]
    fn sizes_that_do_not_fit_are_skipped() {
        assert_eq!(
            summary(&plan(64, 64, &Options::default()).unwrap()),
            [(1, 8), (0, 16), (0, 8)]
        );
        // Non-square, odd sizes: the shorter exemplar side decides.
        let options = Options {
            output_width: 301,
            output_height: 97,
            ..Options::default()
        };
        let levels = plan(200, 70, &options).unwrap();
        assert_eq!(summary(&levels), [(1, 8), (0, 16), (0, 8)]);
        assert_eq!((levels[0].output_width, levels[0].output_height), (151, 49));
        // Tiny exemplar: the fallback level.
        assert_eq!(
            summary(&plan(16, 16, &Options::default()).unwrap()),
            [(0, 8)]
        );
        let options = Options {
            neighbourhood_sizes: vec![32],
            ..Options::default()
        };
        let msg = plan(40, 40, &options).unwrap_err().to_string();
        assert!(
            msg.contains("neighbourhoodSizes") && msg.contains("[32]"),
            "{msg}"
        );
    }

    #[test]
    fn nearest_corner_equals_a_scan() {
        let corners = [0, 2, 4, 6, 8, 10, 12, 13];
        for t in -30..=70 {
            let target = f64::from(t) * 0.25;
            let mut best = 0;
            for (i, &c) in corners.iter().enumerate() {
                if (c as f64 - target).abs() < (corners[best] as f64 - target).abs() {
                    best = i;
                }
            }
            assert_eq!(nearest_corner(&corners, target), best, "target {target}");
        }
    }

    #[test]
    fn grid_covers_the_border() {
        assert_eq!(grid_axis(20, 8, 2, false), [0, 2, 4, 6, 8, 10, 12]);
        assert_eq!(grid_axis(21, 8, 2, false), [0, 2, 4, 6, 8, 10, 12, 13]);
        assert_eq!(grid_axis(8, 8, 2, false), [0]);
        assert_eq!(grid_axis(10, 8, 4, true), [0, 4, 8]);
    }
}
