//! The E-step: the output that minimises the (IRLS-weighted) texture energy for fixed matches.
//!
//! Without the gradient term the minimiser is, per pixel, the average of the matched exemplar
//! neighbourhoods that overlap it, weighted by the robust weight omega_p of each neighbourhood
//! and the Gaussian fall-off g inside it. With the gradient term it is the solution of a
//! weighted screened Poisson system ([`crate::solvers::poisson`]), warm-started from the output.

use super::constraints::Constraint;
use crate::core::{Edge, Image, parallel};
use crate::solvers::nn::Pos;
use crate::solvers::poisson::ScreenedPoisson;

/// Conjugate-gradient limits for the gradient-energy solve. It is warm-started from the current
/// output at every iteration and every level (the up-sampled coarser result on a level's first
/// iteration), so 30-40 iterations reach a relative residual of 1e-4 at 64x64 to 256x256
/// (paving_128 at mu = 10: at most 40); the cap is a guard, not the stopping rule.
pub const CG_MAX_ITERATIONS: usize = 200;
/// Relative residual ||b - Ax|| / ||b|| at which the solve stops.
pub const CG_TOLERANCE: f32 = 1e-4;

/// The fixed inputs of one E-step.
pub struct Matches<'a> {
    pub exemplar: &'a Image,
    pub cols: &'a [usize],
    pub rows: &'a [usize],
    pub matches: &'a [Pos],
    /// IRLS weight omega_p of every neighbourhood.
    pub node_weights: &'a [f32],
    /// Gaussian fall-off per neighbourhood pixel, `size * size`.
    pub falloff: &'a [f32],
    pub size: usize,
    pub wrap: bool,
    pub mu: f32,
}

/// The E-step's running sums over the matched neighbourhoods, per output pixel: weights and
/// weighted colours, and with the gradient term the per-edge weights and weighted target
/// differences (indexed by the edge's first pixel). Nodes can be added in parts, so that a
/// session can spread one E-step of a large output over several steps.
pub struct Sums {
    width: usize,
    height: usize,
    channels: usize,
    weight: Vec<f32>,
    colour: Vec<f32>,
    h_weight: Vec<f32>,
    v_weight: Vec<f32>,
    h_diff: Vec<f32>,
    v_diff: Vec<f32>,
    /// The fall-off repeated over the channels, `size * size * channels`: the colour sums of a
    /// row run are then one element-wise loop over contiguous values (made on the first add).
    falloff_channels: Vec<f32>,
}

impl Sums {
    /// Zero sums for an output like `output`.
    #[must_use]
    pub fn new(output: &Image, gradient: bool) -> Self {
        let (w, h, c) = (output.width(), output.height(), output.channels());
        let (h_weight, v_weight, h_diff, v_diff) = if gradient {
            (
                vec![0.0f32; w * h],
                vec![0.0f32; w * h],
                vec![0.0f32; w * h * c],
                vec![0.0f32; w * h * c],
            )
        } else {
            Default::default()
        };
        Sums {
            width: w,
            height: h,
            channels: c,
            weight: vec![0.0f32; w * h],
            colour: vec![0.0f32; w * h * c],
            h_weight,
            v_weight,
            h_diff,
            v_diff,
            falloff_channels: Vec::new(),
        }
    }

    /// The bands of [`BAND_ROWS`] output rows the sums are cut into.
    #[must_use]
    pub fn bands(&self) -> std::ops::Range<usize> {
        0..self.height.div_ceil(BAND_ROWS)
    }

    /// Adds the matched neighbourhoods of `nodes` to the output rows of `bands` (of
    /// [`Sums::bands`]). The bands are summed in parallel, each over the nodes that reach it in
    /// node order: every pixel adds the same terms in the same order as one pass over the
    /// nodes, so the sums are the same to the bit at any thread count, and whether the nodes or
    /// the bands come in parts.
    pub fn add(
        &mut self,
        m: &Matches<'_>,
        nodes: std::ops::Range<usize>,
        bands: std::ops::Range<usize>,
    ) {
        let (w, h, c) = (self.width, self.height, self.channels);
        let gradient = m.mu > 0.0;
        let Sums {
            weight,
            colour,
            h_weight,
            v_weight,
            h_diff,
            v_diff,
            falloff_channels,
            ..
        } = self;
        if falloff_channels.len() != m.falloff.len() * c {
            *falloff_channels = m
                .falloff
                .iter()
                .flat_map(|&g| std::iter::repeat_n(g, c))
                .collect();
        }
        let plain: Option<Plain> = match (m.size, c) {
            _ if m.wrap || gradient => None,
            (8, 3) => Some(add_plain::<8, 3, 24>),
            (16, 3) => Some(add_plain::<16, 3, 48>),
            (32, 3) => Some(add_plain::<32, 3, 96>),
            (8, 1) => Some(add_plain::<8, 1, 8>),
            (16, 1) => Some(add_plain::<16, 1, 16>),
            (32, 1) => Some(add_plain::<32, 1, 32>),
            _ => None,
        };
        let count = h.div_ceil(BAND_ROWS);
        let mut slices = [
            cut_bands(weight, w, count),
            cut_bands(colour, w * c, count),
            cut_bands(h_weight, w, count),
            cut_bands(v_weight, w, count),
            cut_bands(h_diff, w * c, count),
            cut_bands(v_diff, w * c, count),
        ]
        .map(Vec::into_iter);
        let mut bands: Vec<Band<'_>> = (0..count)
            .map(|b| {
                let [weight, colour, h_weight, v_weight, h_diff, v_diff] = slices
                    .each_mut()
                    .map(|it| it.next().expect("a slice per band"));
                Band {
                    rows: b * BAND_ROWS..h.min((b + 1) * BAND_ROWS),
                    weight,
                    colour,
                    h_weight,
                    v_weight,
                    h_diff,
                    v_diff,
                }
            })
            .skip(bands.start)
            .take(bands.len())
            .collect();
        let falloff_channels = &falloff_channels[..];
        parallel::for_each_piece_mut(&mut bands, 1, |_, band| {
            let band = &mut band[0];
            match plain {
                Some(plain) => plain(m, nodes.clone(), w, falloff_channels, band),
                None => band.add(m, nodes.clone(), (w, h, c), falloff_channels),
            }
        });
    }

    /// Turns the sums into the output: the weighted average, or with the gradient term the
    /// screened Poisson solve; with the constraint's term when given. Returns the CG
    /// iterations (0 without the gradient term).
    pub fn finish(
        self,
        m: &Matches<'_>,
        output: &mut Image,
        constraint: Option<&Constraint>,
    ) -> usize {
        let (w, h, c) = (self.width, self.height, self.channels);
        let gradient = m.mu > 0.0;
        let Sums {
            mut weight,
            mut colour,
            h_weight,
            v_weight,
            h_diff,
            v_diff,
            ..
        } = self;
        if let Some(constraint) = constraint {
            constraint.add_to_e_step(&mut colour, &mut weight);
        }
        let out = output.data_mut();
        if !gradient {
            // Per pixel, so in pieces of rows in parallel.
            let rows = BAND_ROWS * w;
            parallel::for_each_piece_mut(out, rows * c, |piece, out| {
                let weight = &weight[piece * rows..];
                let colour = &colour[piece * rows * c..];
                for (i, px) in out.chunks_exact_mut(c).enumerate() {
                    let wsum = weight[i];
                    if wsum > 0.0 {
                        for (v, &sum) in px.iter_mut().zip(&colour[i * c..(i + 1) * c]) {
                            *v = sum / wsum;
                        }
                    }
                }
            });
            return 0;
        }
        let system = ScreenedPoisson {
            width: w,
            height: h,
            wrap: m.wrap,
            mu: m.mu,
            data_weight: &weight,
            h_weight: &h_weight,
            v_weight: &v_weight,
        };
        let plane = |src: &[f32], k: usize| -> Vec<f32> {
            src.iter().skip(k).step_by(c).copied().collect()
        };
        let mut b = vec![0.0f32; w * h];
        let mut iterations = 0;
        for k in 0..c {
            system.right_hand_side(
                &plane(&colour, k),
                &plane(&h_diff, k),
                &plane(&v_diff, k),
                &mut b,
            );
            let mut x = plane(out, k);
            iterations = iterations.max(system.solve(&b, &mut x, CG_MAX_ITERATIONS, CG_TOLERANCE));
            for (i, v) in x.into_iter().enumerate() {
                out[i * c + k] = v;
            }
        }
        iterations
    }
}

/// Output rows in a band of [`Sums::add`]: fixed, so the bands do not depend on the thread
/// count.
const BAND_ROWS: usize = 8;

/// The sums of one band of output rows: the rows of `rows`, their slices of each sum.
struct Band<'a> {
    rows: std::ops::Range<usize>,
    weight: &'a mut [f32],
    colour: &'a mut [f32],
    h_weight: &'a mut [f32],
    v_weight: &'a mut [f32],
    h_diff: &'a mut [f32],
    v_diff: &'a mut [f32],
}

/// `values` (rows of `per_row` values) cut into `count` bands of [`BAND_ROWS`] rows; an empty
/// `values` (a sum the E-step does not keep) gives empty bands.
fn cut_bands(values: &mut [f32], per_row: usize, count: usize) -> Vec<&mut [f32]> {
    if values.is_empty() {
        (0..count).map(|_| <&mut [f32]>::default()).collect()
    } else {
        values.chunks_mut(BAND_ROWS * per_row).collect()
    }
}

/// The signature of [`add_plain`]'s instances.
type Plain = fn(&Matches<'_>, std::ops::Range<usize>, usize, &[f32], &mut Band<'_>);

/// The nodes of `nodes`, in order, whose neighbourhood rows `oy..oy + size` (modulo `height`
/// when the output wraps) reach the output rows `band`.
fn nodes_reaching<'a>(
    m: &'a Matches<'_>,
    nodes: std::ops::Range<usize>,
    band: std::ops::Range<usize>,
    height: usize,
) -> impl Iterator<Item = usize> + 'a {
    let nx = m.cols.len();
    let (size, wrap) = (m.size, m.wrap);
    let reaches = move |oy: usize| {
        let meets = |top: usize| top < band.end && top + size > band.start;
        meets(oy) || (wrap && oy + size > height && band.start < oy + size - height)
    };
    let first_row = nodes.start / nx;
    let last_row = nodes.end.div_ceil(nx);
    (first_row..last_row)
        .filter(move |&r| reaches(m.rows[r]))
        .flat_map(move |r| (r * nx).max(nodes.start)..((r + 1) * nx).min(nodes.end))
}

impl Band<'_> {
    /// Adds the matched neighbourhoods of `nodes` to this band's rows: any neighbourhood size,
    /// wrapping outputs and the gradient term.
    fn add(
        &mut self,
        m: &Matches<'_>,
        nodes: std::ops::Range<usize>,
        (w, h, c): (usize, usize, usize),
        falloff_channels: &[f32],
    ) {
        let (ew, eh) = (m.exemplar.width(), m.exemplar.height());
        let ex = m.exemplar.data();
        let gradient = m.mu > 0.0;
        let nx = m.cols.len();
        let y0 = self.rows.start;
        for node in nodes_reaching(m, nodes, self.rows.clone(), h) {
            let (z, omega) = (m.matches[node], m.node_weights[node]);
            let (ox, oy) = (m.cols[node % nx], m.rows[node / nx]);
            for dy in 0..m.size {
                let y = if m.wrap { (oy + dy) % h } else { oy + dy };
                if !self.rows.contains(&y) {
                    continue;
                }
                let zy = z.y as usize + dy;
                let falloff = &m.falloff[dy * m.size..(dy + 1) * m.size];
                // The row's pixels as at most two runs of contiguous output columns (the second
                // when the neighbourhood wraps past the right border), so the inner loops run
                // over plain slices.
                let first = if m.wrap { m.size.min(w - ox) } else { m.size };
                for (x0, dx0, len) in [(ox, 0, first), (0, first, m.size - first)] {
                    if len == 0 {
                        continue;
                    }
                    let i = (y - y0) * w + x0;
                    let zi = zy * ew + z.x as usize + dx0;
                    let g = &falloff[dx0..dx0 + len];
                    let row_start = (dy * m.size + dx0) * c;
                    accumulate(
                        omega,
                        g,
                        &falloff_channels[row_start..row_start + len * c],
                        &ex[zi * c..(zi + len) * c],
                        &mut self.weight[i..i + len],
                        &mut self.colour[i * c..(i + len) * c],
                    );
                    if gradient {
                        // Forward differences of the exemplar, zero past its border (as in the
                        // feature map the M-step compares).
                        let zx = z.x as usize + dx0;
                        let down = (zy + 1).min(eh - 1) * ew + zx;
                        accumulate_differences(
                            c,
                            omega,
                            g,
                            &ex[(zy * ew + zx) * c..],
                            &ex[down * c..],
                            ew - zx,
                            (
                                &mut self.h_weight[i..i + len],
                                &mut self.h_diff[i * c..(i + len) * c],
                            ),
                            (
                                &mut self.v_weight[i..i + len],
                                &mut self.v_diff[i * c..(i + len) * c],
                            ),
                        );
                    }
                }
            }
        }
    }
}

/// [`Band::add`]'s colour sums for an output that does not wrap, without the gradient term,
/// for neighbourhoods `N` pixels a side of `C` channels (`NC = N * C`): every row of a
/// neighbourhood is one run of a length known at compile time, so a row costs its two slices
/// and [`accumulate_any`]'s two loops, where the general loop also decided per row whether the
/// row wraps and which fixed length it has (for 8x8 neighbourhoods as much work as the sums).
/// The same sums, added in the same order.
fn add_plain<const N: usize, const C: usize, const NC: usize>(
    m: &Matches<'_>,
    nodes: std::ops::Range<usize>,
    w: usize,
    falloff_channels: &[f32],
    band: &mut Band<'_>,
) {
    let (ew, ex) = (m.exemplar.width(), m.exemplar.data());
    let nx = m.cols.len();
    let fixed = "runs of the neighbourhood's size";
    let rows = band.rows.clone();
    for node in nodes_reaching(m, nodes, rows.clone(), usize::MAX) {
        let (z, omega) = (m.matches[node], m.node_weights[node]);
        let (ox, oy) = (m.cols[node % nx], m.rows[node / nx]);
        let first = rows.start.max(oy) - oy;
        let last = (rows.end - oy).min(N);
        for dy in first..last {
            let i = (oy + dy - rows.start) * w + ox;
            let zi = (z.y as usize + dy) * ew + z.x as usize;
            let g: &[f32; N] = m.falloff[dy * N..(dy + 1) * N].try_into().expect(fixed);
            let g_channels: &[f32; NC] = falloff_channels[dy * NC..(dy + 1) * NC]
                .try_into()
                .expect(fixed);
            let z: &[f32; NC] = ex[zi * C..zi * C + NC].try_into().expect(fixed);
            let weight: &mut [f32; N] = (&mut band.weight[i..i + N]).try_into().expect(fixed);
            let colour: &mut [f32; NC] = (&mut band.colour[i * C..i * C + NC])
                .try_into()
                .expect(fixed);
            accumulate_any(omega, g, g_channels, z, weight, colour);
        }
    }
}

/// Adds one row run of a matched neighbourhood: `weight += omega g` and `colour += omega g z`
/// per pixel, `g_channels` being `g` repeated over the channels. Two element-wise loops over
/// contiguous values, which vectorise (a loop over pixels with the channels inside does not).
/// Whole RGB or grey rows of the usual widths (8, 16, 32) run in loops of a fixed length: a loop
/// of a length known only at run time spends as long on its set-up and remainder as on 24
/// values.
#[inline]
fn accumulate(
    omega: f32,
    g: &[f32],
    g_channels: &[f32],
    z: &[f32],
    weight: &mut [f32],
    colour: &mut [f32],
) {
    match (g.len(), colour.len()) {
        (8, 8) => accumulate_fixed::<8, 8>(omega, g, g_channels, z, weight, colour),
        (16, 16) => accumulate_fixed::<16, 16>(omega, g, g_channels, z, weight, colour),
        (32, 32) => accumulate_fixed::<32, 32>(omega, g, g_channels, z, weight, colour),
        (8, 24) => accumulate_fixed::<8, 24>(omega, g, g_channels, z, weight, colour),
        (16, 48) => accumulate_fixed::<16, 48>(omega, g, g_channels, z, weight, colour),
        (32, 96) => accumulate_fixed::<32, 96>(omega, g, g_channels, z, weight, colour),
        _ => accumulate_any(omega, g, g_channels, z, weight, colour),
    }
}

/// [`accumulate`] for `N` pixels of `NC` values: the same loops, over lengths the compiler
/// knows once it inlines them.
#[inline]
fn accumulate_fixed<const N: usize, const NC: usize>(
    omega: f32,
    g: &[f32],
    g_channels: &[f32],
    z: &[f32],
    weight: &mut [f32],
    colour: &mut [f32],
) {
    let (Ok(g), Ok(g_channels), Ok(z), Ok(weight), Ok(colour)) = (
        <&[f32; N]>::try_from(g),
        <&[f32; NC]>::try_from(g_channels),
        <&[f32; NC]>::try_from(z),
        <&mut [f32; N]>::try_from(weight),
        <&mut [f32; NC]>::try_from(colour),
    ) else {
        unreachable!("accumulate dispatches on the lengths");
    };
    accumulate_any(omega, g, g_channels, z, weight, colour);
}

/// [`accumulate`] for any run.
#[inline(always)]
fn accumulate_any(
    omega: f32,
    g: &[f32],
    g_channels: &[f32],
    z: &[f32],
    weight: &mut [f32],
    colour: &mut [f32],
) {
    for (wk, gk) in weight.iter_mut().zip(g) {
        *wk += omega * gk;
    }
    for ((ck, gk), zk) in colour.iter_mut().zip(g_channels).zip(z) {
        *ck += omega * gk * zk;
    }
}

/// Adds the gradient targets of one row run: `z` is the exemplar from the run's first pixel
/// (`room` pixels to the end of its row), `below` the row beneath (clamped at the bottom);
/// horizontal differences are zero at the exemplar's last column.
#[allow(clippy::too_many_arguments)]
fn accumulate_differences(
    c: usize,
    omega: f32,
    g: &[f32],
    z: &[f32],
    below: &[f32],
    room: usize,
    (h_weight, h_diff): (&mut [f32], &mut [f32]),
    (v_weight, v_diff): (&mut [f32], &mut [f32]),
) {
    for (j, &gj) in g.iter().enumerate() {
        let gw = omega * gj;
        h_weight[j] += gw;
        v_weight[j] += gw;
        let right = if j + 1 < room { j + 1 } else { j };
        for k in 0..c {
            let here = z[j * c + k];
            h_diff[j * c + k] += gw * (z[right * c + k] - here);
            v_diff[j * c + k] += gw * (below[j * c + k] - here);
        }
    }
}

/// The floor of a distance in [`robust_weight`].
const MIN_DISTANCE: f32 = 1e-3;

/// The IRLS weight omega_p = ||x_p - z_p||^(r - 2) from a squared distance. The distance is
/// floored at `MIN_DISTANCE` so that a perfect match gets a large but finite weight.
#[must_use]
pub fn robust_weight(squared_distance: f32, r: f32) -> f32 {
    if r == 2.0 {
        return 1.0;
    }
    // ||d||^(r - 2) = (d^2)^((r - 2) / 2), the floor applied to the square.
    crate::core::power::pow_positive(
        squared_distance.max(MIN_DISTANCE * MIN_DISTANCE),
        0.5 * (r - 2.0),
    )
}

/// The IRLS weight of every squared distance (1 where it is infinite: before the first
/// M-step) into `weights`, and the texture energy sum_p d_p^(r/2) in the same pass: d^(r/2) =
/// d * d^((r-2)/2) = d * omega wherever omega's floor does not apply, so the energy needs no
/// power of its own (a double-precision power per node costs 3% of a 1024x1024 synthesis in
/// wasm).
pub fn robust_weights(distances: &[f32], r: f32, weights: &mut Vec<f32>) -> f64 {
    let half_r = f64::from(r) / 2.0;
    let term = |d: f32| -> (f32, f64) {
        if d.is_finite() {
            let weight = robust_weight(d, r);
            let term = if d.sqrt() >= MIN_DISTANCE {
                f64::from(d) * f64::from(weight)
            } else {
                crate::core::math::pow(f64::from(d), half_r)
            };
            (weight, term)
        } else {
            (1.0, crate::core::math::pow(f64::from(d), half_r))
        }
    };
    // The powers per node in pieces in parallel; the energy summed in node order, one node
    // after another, so that it is the same to the bit at any thread count.
    const PIECE: usize = 1 << 14;
    let pieces = parallel::map(distances.len().div_ceil(PIECE), |p| {
        let part = &distances[p * PIECE..distances.len().min((p + 1) * PIECE)];
        part.iter().map(|&d| term(d)).collect::<Vec<_>>()
    });
    weights.clear();
    let mut sum = 0.0f64;
    for (weight, term) in pieces.into_iter().flatten() {
        weights.push(weight);
        sum += term;
    }
    sum
}

/// Whether `Edge::Wrap` applies.
#[must_use]
pub fn edge(wrap: bool) -> Edge {
    if wrap { Edge::Wrap } else { Edge::Clamp }
}

#[cfg(test)]
#[path = "e_step_tests.rs"]
mod tests;
