//! Weighted screened Poisson equation on a pixel grid, solved by preconditioned conjugate gradient.
//!
//! The E-step with the gradient energy (Kwatra et al. 2005, section 3, "Gradient-based energy")
//! minimises  sum_i d_i (x_i - t_i)^2 + mu * sum_(i,j) w_ij ((x_j - x_i) - g_ij)^2  over a grid,
//! where the first sum pulls pixels to the averaged colours and the second pulls the differences
//! of neighbouring pixels to the averaged differences of the matched neighbourhoods. Setting the
//! derivative to zero gives (D + mu L_w) x = b with D diagonal and L_w a weighted graph Laplacian:
//! symmetric positive definite whenever some d_i > 0, so conjugate gradient applies. It is
//! warm-started from the previous image, which is already close.

/// The system for one `width` x `height` grid. Edge weights are indexed by their first pixel:
/// `h_weight[y * width + x]` joins (x, y)-(x+1, y), `v_weight[y * width + x]` joins (x, y)-(x, y+1).
/// Without `wrap`, the last column's horizontal and the last row's vertical weights are ignored.
#[derive(Debug, Clone, Copy)]
pub struct ScreenedPoisson<'a> {
    pub width: usize,
    pub height: usize,
    pub wrap: bool,
    pub mu: f32,
    pub data_weight: &'a [f32],
    pub h_weight: &'a [f32],
    pub v_weight: &'a [f32],
}

impl ScreenedPoisson<'_> {
    fn right(&self, x: usize, y: usize) -> Option<usize> {
        if x + 1 < self.width {
            Some(y * self.width + x + 1)
        } else if self.wrap && self.width > 1 {
            Some(y * self.width)
        } else {
            None
        }
    }

    fn down(&self, x: usize, y: usize) -> Option<usize> {
        if y + 1 < self.height {
            Some((y + 1) * self.width + x)
        } else if self.wrap && self.height > 1 {
            Some(x)
        } else {
            None
        }
    }

    /// Calls `f(i, j, w)` for every edge with its weight.
    fn for_each_edge(&self, mut f: impl FnMut(usize, usize, f32)) {
        for y in 0..self.height {
            for x in 0..self.width {
                let i = y * self.width + x;
                if let Some(j) = self.right(x, y) {
                    f(i, j, self.h_weight[i]);
                }
                if let Some(j) = self.down(x, y) {
                    f(i, j, self.v_weight[i]);
                }
            }
        }
    }

    /// `out = (D + mu L_w) x`.
    pub fn apply(&self, x: &[f32], out: &mut [f32]) {
        for ((o, &d), &xi) in out.iter_mut().zip(self.data_weight).zip(x) {
            *o = d * xi;
        }
        let mu = self.mu;
        self.for_each_edge(|i, j, w| {
            let flow = mu * w * (x[i] - x[j]);
            out[i] += flow;
            out[j] -= flow;
        });
    }

    /// The right-hand side for data targets `t` (already multiplied by `d`: `dt_i = d_i t_i`) and
    /// weighted target differences `h_diff`/`v_diff` (`w_ij g_ij`, indexed like the weights).
    pub fn right_hand_side(&self, dt: &[f32], h_diff: &[f32], v_diff: &[f32], b: &mut [f32]) {
        b.copy_from_slice(dt);
        let mu = self.mu;
        for y in 0..self.height {
            for x in 0..self.width {
                let i = y * self.width + x;
                if let Some(j) = self.right(x, y) {
                    b[i] -= mu * h_diff[i];
                    b[j] += mu * h_diff[i];
                }
                if let Some(j) = self.down(x, y) {
                    b[i] -= mu * v_diff[i];
                    b[j] += mu * v_diff[i];
                }
            }
        }
    }

    /// Solves for `x`, starting from its current value, until the residual norm falls below
    /// `tolerance` times the norm of `b` or `max_iterations` pass. Jacobi-preconditioned.
    /// Returns the number of iterations.
    pub fn solve(&self, b: &[f32], x: &mut [f32], max_iterations: usize, tolerance: f32) -> usize {
        let n = x.len();
        let mut diagonal = self.data_weight.to_vec();
        let mu = self.mu;
        self.for_each_edge(|i, j, w| {
            diagonal[i] += mu * w;
            diagonal[j] += mu * w;
        });
        let inverse: Vec<f32> = diagonal
            .iter()
            .map(|&d| if d > 0.0 { 1.0 / d } else { 0.0 })
            .collect();
        let mut r = vec![0.0f32; n];
        self.apply(x, &mut r);
        for (ri, &bi) in r.iter_mut().zip(b) {
            *ri = bi - *ri;
        }
        let b_norm = dot(b, b).sqrt().max(f64::MIN_POSITIVE);
        let mut z: Vec<f32> = r.iter().zip(&inverse).map(|(a, m)| a * m).collect();
        let mut p = z.clone();
        let mut ap = vec![0.0f32; n];
        let mut rz = dot(&r, &z);
        for iteration in 0..max_iterations {
            if dot(&r, &r).sqrt() <= f64::from(tolerance) * b_norm {
                return iteration;
            }
            self.apply(&p, &mut ap);
            let p_ap = dot(&p, &ap);
            if p_ap <= 0.0 {
                return iteration; // converged to machine precision (or a singular direction)
            }
            let alpha = (rz / p_ap) as f32;
            for k in 0..n {
                x[k] += alpha * p[k];
                r[k] -= alpha * ap[k];
                z[k] = r[k] * inverse[k];
            }
            let rz_next = dot(&r, &z);
            let beta = (rz_next / rz) as f32;
            rz = rz_next;
            for k in 0..n {
                p[k] = z[k] + beta * p[k];
            }
        }
        max_iterations
    }
}

fn dot(a: &[f32], b: &[f32]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| f64::from(*x) * f64::from(*y))
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Rng;

    /// Dense Gaussian elimination: the oracle for small systems (indexed loops: they read as
    /// the textbook's).
    #[allow(clippy::needless_range_loop)]
    fn dense_solve(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Vec<f64> {
        let n = b.len();
        for col in 0..n {
            let pivot = (col..n)
                .max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))
                .unwrap();
            a.swap(col, pivot);
            b.swap(col, pivot);
            for row in col + 1..n {
                let f = a[row][col] / a[col][col];
                for k in col..n {
                    a[row][k] -= f * a[col][k];
                }
                b[row] -= f * b[col];
            }
        }
        let mut x = vec![0.0; n];
        for row in (0..n).rev() {
            let s: f64 = (row + 1..n).map(|k| a[row][k] * x[k]).sum();
            x[row] = (b[row] - s) / a[row][row];
        }
        x
    }

    fn random_system(wrap: bool, seed: u64) -> (usize, usize, Vec<f32>, Vec<f32>, Vec<f32>) {
        let (w, h) = (5, 4);
        let mut rng = Rng::new(seed);
        let mut values = |lo: f32| {
            (0..w * h)
                .map(|_| lo + rng.next_f32())
                .collect::<Vec<f32>>()
        };
        let _ = wrap;
        (w, h, values(0.1), values(0.0), values(0.0))
    }

    #[test]
    #[allow(clippy::needless_range_loop)]
    fn cg_matches_dense_elimination_with_and_without_wrap() {
        for wrap in [false, true] {
            let (w, h, d, hw, vw) = random_system(wrap, 7);
            let sys = ScreenedPoisson {
                width: w,
                height: h,
                wrap,
                mu: 10.0,
                data_weight: &d,
                h_weight: &hw,
                v_weight: &vw,
            };
            let mut rng = Rng::new(8);
            let b: Vec<f32> = (0..w * h).map(|_| rng.next_f32() * 4.0 - 2.0).collect();
            // The dense matrix, column by column, through `apply`.
            let n = w * h;
            let mut dense = vec![vec![0.0f64; n]; n];
            let (mut e, mut col) = (vec![0.0f32; n], vec![0.0f32; n]);
            for j in 0..n {
                e.iter_mut().for_each(|v| *v = 0.0);
                e[j] = 1.0;
                sys.apply(&e, &mut col);
                for i in 0..n {
                    dense[i][j] = f64::from(col[i]);
                }
            }
            for i in 0..n {
                for j in 0..n {
                    assert!((dense[i][j] - dense[j][i]).abs() < 1e-5, "symmetric");
                }
            }
            let want = dense_solve(dense, b.iter().map(|&v| f64::from(v)).collect());
            let mut x = vec![0.0; n];
            let iterations = sys.solve(&b, &mut x, 200, 1e-6);
            assert!(iterations < 200);
            for (got, want) in x.iter().zip(&want) {
                assert!((f64::from(*got) - want).abs() < 1e-3, "{got} vs {want}");
            }
            // Warm start from the answer: nothing left to do.
            assert_eq!(sys.solve(&b, &mut x, 200, 1e-3), 0);
        }
    }

    #[test]
    fn zero_mu_is_the_weighted_average_and_rhs_matches_the_energy_gradient() {
        let (w, h, d, hw, vw) = random_system(false, 3);
        let sys = ScreenedPoisson {
            width: w,
            height: h,
            wrap: false,
            mu: 0.0,
            data_weight: &d,
            h_weight: &hw,
            v_weight: &vw,
        };
        let t: Vec<f32> = (0..w * h).map(|i| i as f32 * 0.1).collect();
        let dt: Vec<f32> = t.iter().zip(&d).map(|(a, b)| a * b).collect();
        let mut b = vec![0.0; w * h];
        sys.right_hand_side(&dt, &vec![1.0; w * h], &vec![1.0; w * h], &mut b);
        let mut x = vec![0.0; w * h];
        sys.solve(&b, &mut x, 100, 1e-7);
        assert!(x.iter().zip(&t).all(|(a, b)| (a - b).abs() < 1e-4));

        // With mu > 0 and target differences equal to those of t, t itself is the minimiser.
        let sys = ScreenedPoisson { mu: 10.0, ..sys };
        let h_diff: Vec<f32> = (0..w * h)
            .map(|i| {
                if (i % w) + 1 < w {
                    hw[i] * (t[i + 1] - t[i])
                } else {
                    0.0
                }
            })
            .collect();
        let v_diff: Vec<f32> = (0..w * h)
            .map(|i| {
                if i + w < w * h {
                    vw[i] * (t[i + w] - t[i])
                } else {
                    0.0
                }
            })
            .collect();
        sys.right_hand_side(&dt, &h_diff, &v_diff, &mut b);
        let mut x = vec![0.0; w * h];
        sys.solve(&b, &mut x, 200, 1e-7);
        assert!(x.iter().zip(&t).all(|(a, b)| (a - b).abs() < 1e-3), "{x:?}");
    }
}
