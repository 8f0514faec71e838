//! Feature alignment by deformation (Wu & Yu 2004, section 2.2): the chosen patch is bent a
//! little so that its features land on the context's. Correspondences are recomputed with
//! tau = 10 (tangents count more), made one-to-one, and a thin-plate spline through them, with the
//! patch's bottom and right borders held fixed so that deformations do not accumulate, gives the
//! displacement at every patch pixel; Shepard's method takes over when the spline fails.

use super::matching::{ContextFeature, Correspondence, FeatureIndex, Region, TAU_ALIGN};
use crate::solvers::tps::{Interpolant, SplineFailure, Warp};

/// How the patch was deformed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WarpKind {
    /// No deformation: warping is off, or there was nothing to align.
    None,
    /// A thin-plate spline.
    Spline,
    /// Shepard interpolation, because the spline failed.
    Shepard(SplineFailure),
    /// A warp was fitted but would move pixels farther than a quarter patch: not used.
    Skipped,
    /// Graph-cut placement lays whole-exemplar patches along seams and has no warp, whatever
    /// the `warp` option says (the scan placement warps).
    Unavailable,
}

/// The farthest gdist (tau = 10) a correspondence may have: a pixel or so of position and a few
/// degrees of tangent; anything farther is another feature, not this one misaligned.
pub const MAX_GDIST: f32 = 2.5;

/// The displacement field of a patch: the source pixel of patch pixel (x, y) is
/// (x + dx, y + dy), sampled every pixel.
pub struct Alignment {
    pub kind: WarpKind,
    pub correspondences: Vec<Correspondence>,
    /// `size * size` displacements (all zero for `WarpKind::None` and `Skipped`).
    pub displacement: Vec<(f32, f32)>,
}

/// Aligns the patch at (tx, ty) of the exemplar with the context features.
#[must_use]
pub fn align(
    index: &FeatureIndex,
    context: &[ContextFeature],
    region: Region,
    tx: usize,
    ty: usize,
) -> Alignment {
    let size = region.size;
    let zero = vec![(0.0f32, 0.0f32); size * size];
    let correspondences = index.correspondences(context, tx, ty, TAU_ALIGN, MAX_GDIST);
    let (w, _) = index.size();
    // Control points: each context feature should show the exemplar feature it corresponds to,
    // so the output pixel at x_i reads the patch at x'_i: displacement x'_i - x_i.
    let mut points: Vec<crate::solvers::tps::ControlPoint> = correspondences
        .iter()
        .map(|c| {
            let f = context[c.context];
            let (jx, jy) = (
                (c.target % w) as f64 - tx as f64,
                (c.target / w) as f64 - ty as f64,
            );
            ((f.x as f64, f.y as f64), (jx - f.x as f64, jy - f.y as f64))
        })
        .collect();
    if points.iter().all(|p| p.1 == (0.0, 0.0)) {
        return Alignment {
            kind: WarpKind::None,
            correspondences,
            displacement: zero,
        };
    }
    // The bottom and right borders stay where they are (the paper), and so does an inner L one
    // context-width inside the context region (ours): the bend is confined to a band along the
    // seam, where it joins the curves, and the patch's interior stays an exact copy. Without it
    // the spline shears the whole patch, and the next patches inherit the shear (measured on
    // the structured samples at patch 64: coherence about 3x plain graph cut's).
    let last = (size - 1) as f64;
    for k in (0..size).step_by(2) {
        points.push(((k as f64, last), (0.0, 0.0)));
        points.push(((last, k as f64), (0.0, 0.0)));
    }
    points.push(((last, last), (0.0, 0.0)));
    let band = region.top.max(region.left).max(2);
    let (inner_x, inner_y) = (region.left + band, region.top + band);
    for k in (0..size).step_by(2) {
        if region.top > 0 && inner_y < size - 1 && k >= region.left {
            points.push(((k as f64, inner_y as f64), (0.0, 0.0)));
        }
        if region.left > 0 && inner_x < size - 1 && k >= region.top {
            points.push(((inner_x as f64, k as f64), (0.0, 0.0)));
        }
    }
    points.sort_by(|a, b| a.0.0.total_cmp(&b.0.0).then(a.0.1.total_cmp(&b.0.1)));
    points.dedup_by(|a, b| a.0 == b.0);
    let largest = points
        .iter()
        .map(|p| crate::core::math::hypot(p.1.0, p.1.1))
        .fold(0.0f64, f64::max);
    let mut warp = Warp::fit(&points);
    // A spline overshoots between far-apart constraints; the paper wants "a small amount of
    // deformation". Past 1.5 times the largest constrained move (measured every 4 pixels), use
    // Shepard's method, whose values stay within the constraints'.
    if let Warp::Spline(spline) = &warp {
        let overshoot = (0..size).step_by(4).any(|y| {
            (0..size).step_by(4).any(|x| {
                let (dx, dy) = spline.at(x as f64, y as f64);
                crate::core::math::hypot(dx, dy) > 1.5 * largest + 0.25
            })
        });
        if overshoot {
            warp = Warp::Shepard(
                crate::solvers::tps::Shepard::new(&points),
                SplineFailure::MissesConstraints,
            );
        }
    }
    let kind = match &warp {
        Warp::Spline(_) => WarpKind::Spline,
        Warp::Shepard(_, why) => WarpKind::Shepard(*why),
    };
    let mut displacement = Vec::with_capacity(size * size);
    let limit = size as f32 / 4.0;
    for y in 0..size {
        for x in 0..size {
            let (dx, dy) = warp.at(x as f64, y as f64);
            let d = (dx as f32, dy as f32);
            if !d.0.is_finite() || !d.1.is_finite() || crate::core::math::hypotf(d.0, d.1) > limit {
                return Alignment {
                    kind: WarpKind::Skipped,
                    correspondences,
                    displacement: zero,
                };
            }
            displacement.push(d);
        }
    }
    Alignment {
        kind,
        correspondences,
        displacement,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::methods::features::detect::FeatureMap;

    #[test]
    fn a_shifted_line_is_bent_onto_the_context_and_the_far_borders_stay() {
        // Exemplar: a horizontal line at y = 12. Context: the same line one pixel higher, at
        // y = 11, in the patch's top-left region.
        let (w, h) = (40, 40);
        let mut map = FeatureMap {
            width: w,
            height: h,
            mask: vec![false; w * h],
            angle: vec![0.0; w * h],
            response: vec![0.0; w * h],
            threshold: 1.0,
        };
        for x in 0..w {
            map.mask[12 * w + x] = true;
        }
        let index = FeatureIndex::new(&map);
        let context: Vec<ContextFeature> = (0..8)
            .map(|x| ContextFeature {
                x,
                y: 11,
                angle: 0.0,
            })
            .collect();
        let a = align(
            &index,
            &context,
            Region {
                size: 24,
                top: 0,
                left: 0,
            },
            0,
            0,
        );
        assert_eq!(a.kind, WarpKind::Spline);
        assert_eq!(a.correspondences.len(), 8);
        for x in 0..8 {
            let (dx, dy) = a.displacement[11 * 24 + x];
            assert!(
                dx.abs() < 1e-3 && (dy - 1.0).abs() < 1e-3,
                "({x}): {dx} {dy}"
            );
        }
        for k in 0..24 {
            let (bx, by) = a.displacement[23 * 24 + k];
            let (rx, ry) = a.displacement[k * 24 + 23];
            assert!(
                bx.hypot(by) < 0.06 && rx.hypot(ry) < 0.06,
                "borders fixed at {k}"
            );
        }
    }
}
