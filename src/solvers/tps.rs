//! Scattered-data interpolation of 2-D displacements, for warping a patch so that its features
//! meet the ones already placed (Wu & Yu 2004, section 2.2): the thin-plate spline (Meinguet
//! 1979), which has the least bending energy of all interpolants, and Shepard's inverse-distance
//! weighting as the fallback when the spline's linear system is ill-conditioned or its result
//! misses the constraints.

/// A control point: its position and the displacement wanted there.
pub type ControlPoint = ((f64, f64), (f64, f64));

/// A displacement field given at control points.
pub trait Interpolant {
    /// The displacement at (x, y).
    fn at(&self, x: f64, y: f64) -> (f64, f64);
}

/// A fitted thin-plate spline: f(p) = a0 + a1 x + a2 y + sum_i w_i U(|p - c_i|), U(r) = r^2 ln r^2,
/// one for each displacement component.
#[derive(Debug, Clone)]
pub struct ThinPlateSpline {
    centres: Vec<(f64, f64)>,
    /// Per component: the n kernel weights, then a0, a1, a2.
    coefficients: [Vec<f64>; 2],
}

fn kernel(r2: f64) -> f64 {
    if r2 <= 0.0 {
        0.0
    } else {
        r2 * crate::core::math::ln(r2)
    }
}

/// Why a spline could not be used.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SplineFailure {
    /// Fewer than three points, or all on one line: the affine part is undetermined.
    Degenerate,
    /// The system's pivots fell below the tolerance (coincident points, for instance).
    IllConditioned,
    /// The solution misses a control point by more than the tolerance.
    MissesConstraints,
}

/// Relative pivot size below which the system counts as singular.
const PIVOT_TOLERANCE: f64 = 1e-10;
/// How far (in pixels) the fit may miss a control point.
pub const CONSTRAINT_TOLERANCE: f64 = 0.05;

impl ThinPlateSpline {
    /// Fits the spline through `points` (position, displacement).
    pub fn fit(points: &[ControlPoint]) -> Result<ThinPlateSpline, SplineFailure> {
        let n = points.len();
        if n < 3 {
            return Err(SplineFailure::Degenerate);
        }
        let (x0, y0) = points[0].0;
        let spread = points.iter().skip(1).any(|&((x1, y1), _)| {
            points
                .iter()
                .any(|&((x2, y2), _)| ((x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0)).abs() > 1e-9)
        });
        if !spread {
            return Err(SplineFailure::Degenerate);
        }
        // The (n + 3) x (n + 3) system [K P; P^T 0] [w; a] = [v; 0], two right-hand sides.
        let size = n + 3;
        let mut a = vec![0.0f64; size * size];
        let mut b = vec![[0.0f64; 2]; size];
        for (i, &((xi, yi), (dx, dy))) in points.iter().enumerate() {
            for (j, &((xj, yj), _)) in points.iter().enumerate() {
                a[i * size + j] = kernel((xi - xj).powi(2) + (yi - yj).powi(2));
            }
            for (k, v) in [1.0, xi, yi].into_iter().enumerate() {
                a[i * size + n + k] = v;
                a[(n + k) * size + i] = v;
            }
            b[i] = [dx, dy];
        }
        solve_in_place(&mut a, &mut b, size).ok_or(SplineFailure::IllConditioned)?;
        let spline = ThinPlateSpline {
            centres: points.iter().map(|p| p.0).collect(),
            coefficients: [
                b.iter().map(|v| v[0]).collect(),
                b.iter().map(|v| v[1]).collect(),
            ],
        };
        let misses = points.iter().any(|&((x, y), (dx, dy))| {
            let (fx, fy) = spline.at(x, y);
            !fx.is_finite()
                || !fy.is_finite()
                || crate::core::math::hypot(fx - dx, fy - dy) > CONSTRAINT_TOLERANCE
        });
        if misses {
            return Err(SplineFailure::MissesConstraints);
        }
        Ok(spline)
    }
}

impl Interpolant for ThinPlateSpline {
    fn at(&self, x: f64, y: f64) -> (f64, f64) {
        let n = self.centres.len();
        let mut out = [0.0f64; 2];
        for (c, coef) in out.iter_mut().zip(&self.coefficients) {
            let mut v = coef[n] + coef[n + 1] * x + coef[n + 2] * y;
            for (i, &(cx, cy)) in self.centres.iter().enumerate() {
                v += coef[i] * kernel((x - cx).powi(2) + (y - cy).powi(2));
            }
            *c = v;
        }
        (out[0], out[1])
    }
}

/// Gaussian elimination with partial pivoting on a dense `size` x `size` matrix with two
/// right-hand sides; None if a pivot is negligible against the largest entry.
fn solve_in_place(a: &mut [f64], b: &mut [[f64; 2]], size: usize) -> Option<()> {
    let scale = a.iter().fold(0.0f64, |m, v| m.max(v.abs())).max(1e-300);
    for col in 0..size {
        let pivot = (col..size)
            .max_by(|&i, &j| a[i * size + col].abs().total_cmp(&a[j * size + col].abs()))?;
        if a[pivot * size + col].abs() < PIVOT_TOLERANCE * scale {
            return None;
        }
        if pivot != col {
            for k in 0..size {
                a.swap(pivot * size + k, col * size + k);
            }
            b.swap(pivot, col);
        }
        let p = a[col * size + col];
        for row in col + 1..size {
            let f = a[row * size + col] / p;
            if f == 0.0 {
                continue;
            }
            for k in col..size {
                a[row * size + k] -= f * a[col * size + k];
            }
            b[row][0] -= f * b[col][0];
            b[row][1] -= f * b[col][1];
        }
    }
    for row in (0..size).rev() {
        let mut s = b[row];
        for k in row + 1..size {
            s[0] -= a[row * size + k] * b[k][0];
            s[1] -= a[row * size + k] * b[k][1];
        }
        let p = a[row * size + row];
        b[row] = [s[0] / p, s[1] / p];
    }
    Some(())
}

/// Shepard's inverse-distance-squared weighting: exact at the control points, always defined.
#[derive(Debug, Clone)]
pub struct Shepard {
    points: Vec<ControlPoint>,
}

impl Shepard {
    #[must_use]
    pub fn new(points: &[ControlPoint]) -> Shepard {
        Shepard {
            points: points.to_vec(),
        }
    }
}

impl Interpolant for Shepard {
    fn at(&self, x: f64, y: f64) -> (f64, f64) {
        let (mut sx, mut sy, mut sw) = (0.0, 0.0, 0.0);
        for &((px, py), (dx, dy)) in &self.points {
            let d2 = (x - px).powi(2) + (y - py).powi(2);
            if d2 < 1e-12 {
                return (dx, dy);
            }
            let w = 1.0 / d2;
            sx += w * dx;
            sy += w * dy;
            sw += w;
        }
        if sw == 0.0 {
            (0.0, 0.0)
        } else {
            (sx / sw, sy / sw)
        }
    }
}

/// The warp Wu & Yu use: a thin-plate spline, or Shepard's method when the spline fails.
pub enum Warp {
    Spline(ThinPlateSpline),
    Shepard(Shepard, SplineFailure),
}

impl Warp {
    #[must_use]
    pub fn fit(points: &[ControlPoint]) -> Warp {
        match ThinPlateSpline::fit(points) {
            Ok(s) => Warp::Spline(s),
            Err(why) => Warp::Shepard(Shepard::new(points), why),
        }
    }
}

impl Interpolant for Warp {
    fn at(&self, x: f64, y: f64) -> (f64, f64) {
        match self {
            Warp::Spline(s) => s.at(x, y),
            Warp::Shepard(s, _) => s.at(x, y),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Rng;

    fn random_points(n: usize, seed: u64) -> Vec<ControlPoint> {
        let mut rng = Rng::new(seed);
        (0..n)
            .map(|_| {
                (
                    (rng.next_f64() * 32.0, rng.next_f64() * 32.0),
                    (rng.next_f64() * 2.0 - 1.0, rng.next_f64() * 2.0 - 1.0),
                )
            })
            .collect()
    }

    #[test]
    fn the_spline_interpolates_its_points_and_keeps_fixed_borders() {
        // Features moved a little inside a 32x32 patch; the bottom and right borders fixed.
        let mut points = random_points(12, 1)
            .into_iter()
            .map(|((x, y), d)| ((x * 0.7 + 2.0, y * 0.7 + 2.0), d))
            .collect::<Vec<_>>();
        for k in (0..32).step_by(4) {
            points.push(((f64::from(k), 31.0), (0.0, 0.0)));
            points.push(((31.0, f64::from(k)), (0.0, 0.0)));
        }
        points.push(((31.0, 31.0), (0.0, 0.0)));
        let spline = ThinPlateSpline::fit(&points).expect("a well-spread set fits");
        for &((x, y), (dx, dy)) in &points {
            let (fx, fy) = spline.at(x, y);
            assert!((fx - dx).abs() < 1e-6 && (fy - dy).abs() < 1e-6);
        }
        // An affine field is reproduced everywhere (TPS has no bending energy for it).
        let affine: Vec<_> = random_points(8, 2)
            .into_iter()
            .map(|((x, y), _)| ((x, y), (0.1 * x - 0.2 * y + 1.0, 0.05 * y)))
            .collect();
        let s = ThinPlateSpline::fit(&affine).unwrap();
        let (fx, fy) = s.at(7.0, 19.0);
        assert!((fx - (0.7 - 3.8 + 1.0)).abs() < 1e-6 && (fy - 0.95).abs() < 1e-6);
    }

    #[test]
    fn degenerate_configurations_fall_back_to_shepard() {
        let collinear: Vec<_> = (0..6)
            .map(|i| ((f64::from(i), 2.0 * f64::from(i)), (1.0, 0.0)))
            .collect();
        assert_eq!(
            ThinPlateSpline::fit(&collinear).unwrap_err(),
            SplineFailure::Degenerate
        );
        let mut coincident = random_points(6, 3);
        coincident.push((coincident[0].0, (5.0, 5.0)));
        assert_eq!(
            ThinPlateSpline::fit(&coincident).unwrap_err(),
            SplineFailure::IllConditioned
        );
        for points in [collinear, coincident] {
            let warp = Warp::fit(&points);
            assert!(matches!(warp, Warp::Shepard(..)));
            // Shepard is exact at its (first) points and finite everywhere.
            let ((x, y), (dx, dy)) = points[1];
            assert_eq!(warp.at(x, y), (dx, dy));
            let (fx, fy) = warp.at(100.0, -50.0);
            assert!(fx.is_finite() && fy.is_finite());
        }
        assert_eq!(
            ThinPlateSpline::fit(&random_points(2, 4)).unwrap_err(),
            SplineFailure::Degenerate
        );
    }
}
