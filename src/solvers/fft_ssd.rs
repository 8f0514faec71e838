//! The sum of squared differences between the output and a translated patch, for every
//! translation at once, by FFT (graph-cut textures, section 5, eq. 6).
//!
//! Patch pixel `u` placed at offset `t` lands on output pixel `p = u + t`. With weights `w_O` on
//! the output (0 where nothing has been synthesised yet, or a soft validity) and `w_I` on the
//! patch, the cost of a translation and the area it overlaps are
//!
//! ```text
//! C(t) = sum_u w_O(u+t) w_I(u) |O(u+t) - I(u)|^2
//!      = sum_u (w_O O^2)(u+t) w_I(u) + sum_u w_O(u+t) (w_I I^2)(u) - 2 sum_u (w_O O)(u+t) (w_I I)(u)
//! A(t) = sum_u w_O(u+t) w_I(u)
//! ```
//!
//! Each sum is a cross-correlation, a product of spectra: `corr(X, Y) = F^-1(F(X) conj F(Y))`. The
//! paper takes the two squared terms from summed-area tables, which works when one side is a full
//! rectangle; with weights on both sides they are correlations too, so here every term is one.
//! All terms are added in the frequency domain, so a search costs `4 + 2 * channels` forward and
//! two inverse transforms, of which [`SsdSearch::search_keyed`] reuses the patch's `2 + channels`
//! between searches of the same patch. [`SsdMap`] gives `C(t)` (eq. 4 and 6) and `A(t)`, whose ratio is the
//! area-normalised cost of eq. 2 used by entire-patch matching.
//!
//! The transforms run in `f64`: the best matches are small differences of large sums, where `f32`
//! would keep only about three of its seven digits on a 256x256 overlap.

use std::sync::Arc;

use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::{Fft, FftPlanner};

use crate::core::{Error, Image, Result};

/// Which translations exist and what lies beyond the output's border.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Boundary {
    /// The output is a bounded picture: every translation at which the patch overlaps it by at
    /// least one pixel, `-(patch width - 1) ..= output width - 1` along x (likewise y). Patch
    /// pixels that fall outside the output count for nothing.
    #[default]
    Open,
    /// The output is a torus (tileable texture): translations `0 .. output width` (likewise y),
    /// and patch pixels past the border wrap around to the other side.
    Periodic,
}

/// Overlaps whose total weight is below this count as no overlap: the transform leaves noise of
/// about `1e-12` where the true area is zero, and `C / A` there would be meaningless.
pub const MIN_AREA: f32 = 1e-6;

/// The largest transform, in values (`2048 x 2048`): five spectra of it already take 170 MB.
pub const MAX_TRANSFORM_VALUES: usize = 1 << 22;

/// The cost `C(t)` and overlap area `A(t)` of every translation `t`, row by row.
#[derive(Debug, Clone, PartialEq)]
pub struct SsdMap {
    width: usize,
    height: usize,
    first_offset: (isize, isize),
    costs: Vec<f32>,
    areas: Vec<f32>,
}

impl SsdMap {
    /// The number of translations along x.
    #[must_use]
    pub fn width(&self) -> usize {
        self.width
    }

    /// The number of translations along y.
    #[must_use]
    pub fn height(&self) -> usize {
        self.height
    }

    /// The translation at index 0: `(-(patch width - 1), -(patch height - 1))` for
    /// [`Boundary::Open`], `(0, 0)` for [`Boundary::Periodic`].
    #[must_use]
    pub fn first_offset(&self) -> (isize, isize) {
        self.first_offset
    }

    /// `C(t)` for every translation, row-major: never negative, 0 where nothing overlaps.
    #[must_use]
    pub fn costs(&self) -> &[f32] {
        &self.costs
    }

    /// `A(t)` for every translation: the number of overlapping pixels, each counted with the
    /// product of its two weights; 0 where nothing overlaps.
    #[must_use]
    pub fn areas(&self) -> &[f32] {
        &self.areas
    }

    /// The translation at `index` of [`SsdMap::costs`].
    #[must_use]
    pub fn offset(&self, index: usize) -> (isize, isize) {
        (
            self.first_offset.0 + (index % self.width) as isize,
            self.first_offset.1 + (index / self.width) as isize,
        )
    }

    /// `(C(t), A(t))` for the translation `(tx, ty)`, or `None` outside the map.
    #[must_use]
    pub fn get(&self, tx: isize, ty: isize) -> Option<(f32, f32)> {
        let i = usize::try_from(tx - self.first_offset.0).ok()?;
        let j = usize::try_from(ty - self.first_offset.1).ok()?;
        (i < self.width && j < self.height).then(|| {
            let index = j * self.width + i;
            (self.costs[index], self.areas[index])
        })
    }
}

/// A reusable FFT SSD search: it keeps the FFT plans and buffers between calls, since a synthesis
/// searches once per patch placement with the same sizes every time.
pub struct SsdSearch {
    real_planner: RealFftPlanner<f64>,
    complex_planner: FftPlanner<f64>,
    transform: Option<Transform2d>,
    /// Real-valued work image of the transform size.
    field: Vec<f64>,
    /// Spectra: output weights, accumulated cost, and a temporary.
    spectra: [Vec<Complex<f64>>; 3],
    /// The patch side of the last keyed search.
    patch_cache: Option<PatchSpectra>,
}

/// Transforms of a patch's weights, weighted squared norms and weighted channels.
struct PatchSpectra {
    key: Option<u64>,
    nx: usize,
    ny: usize,
    spectra: Vec<Vec<Complex<f64>>>,
}

impl std::fmt::Debug for SsdSearch {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let size = self.transform.as_ref().map(|t| (t.nx, t.ny));
        f.debug_struct("SsdSearch")
            .field("transform_size", &size)
            .finish_non_exhaustive()
    }
}

/// Computes [`SsdMap`] once; use an [`SsdSearch`] to search repeatedly.
pub fn ssd_map(
    output: &Image,
    output_weights: Option<&[f32]>,
    patch: &Image,
    patch_weights: Option<&[f32]>,
    boundary: Boundary,
) -> Result<SsdMap> {
    SsdSearch::new().search(output, output_weights, patch, patch_weights, boundary)
}

impl Default for SsdSearch {
    fn default() -> Self {
        Self::new()
    }
}

impl SsdSearch {
    #[must_use]
    pub fn new() -> Self {
        SsdSearch {
            real_planner: RealFftPlanner::new(),
            complex_planner: FftPlanner::new(),
            transform: None,
            field: Vec::new(),
            spectra: Default::default(),
            patch_cache: None,
        }
    }

    /// The cost and overlap area of every translation of `patch` over `output`.
    ///
    /// `output_weights` and `patch_weights` hold one weight per pixel (`None`: all 1). A pixel of
    /// weight 0 is not read at all, so unfilled output pixels may hold anything. Fails when the
    /// channel counts differ, a weight buffer has the wrong length, a weight is negative or not
    /// finite, a weighted pixel value is not finite, or the transform would be larger than
    /// [`MAX_TRANSFORM_VALUES`].
    pub fn search(
        &mut self,
        output: &Image,
        output_weights: Option<&[f32]>,
        patch: &Image,
        patch_weights: Option<&[f32]>,
        boundary: Boundary,
    ) -> Result<SsdMap> {
        self.search_keyed(output, output_weights, patch, patch_weights, boundary, None)
    }

    /// Like [`SsdSearch::search`], reusing the patch's transforms from the last call with the
    /// same `patch_key` (and transform size). The caller promises that one key always names the
    /// same patch and patch weights; `None` never reuses. Saves `2 + channels` of the
    /// `4 + 2 * channels` forward transforms.
    pub fn search_keyed(
        &mut self,
        output: &Image,
        output_weights: Option<&[f32]>,
        patch: &Image,
        patch_weights: Option<&[f32]>,
        boundary: Boundary,
        patch_key: Option<u64>,
    ) -> Result<SsdMap> {
        if patch.channels() != output.channels() {
            return Err(Error::InvalidParameter {
                name: "patch",
                reason: format!(
                    "has {} channels but the output has {}",
                    patch.channels(),
                    output.channels()
                ),
            });
        }
        let output = Weighted::new(output, output_weights, ("output", "output weights"))?;
        let patch = Weighted::new(patch, patch_weights, ("patch", "patch weights"))?;
        let (ow, oh) = (output.image.width(), output.image.height());
        let (pw, ph) = (patch.image.width(), patch.image.height());
        let (nx, ny, map_width, map_height, first_offset) = match boundary {
            // Padding to at least `ow + pw - 1` keeps the circular correlation from wrapping.
            Boundary::Open => (
                smooth_size(ow + pw - 1),
                smooth_size(oh + ph - 1),
                ow + pw - 1,
                oh + ph - 1,
                (1 - pw as isize, 1 - ph as isize),
            ),
            Boundary::Periodic => (ow, oh, ow, oh, (0, 0)),
        };
        if nx.saturating_mul(ny) > MAX_TRANSFORM_VALUES {
            return Err(Error::InvalidSize {
                what: "FFT search transform",
                width: nx,
                height: ny,
                reason: format!(
                    "at most {MAX_TRANSFORM_VALUES} values are supported; use a smaller patch or output"
                ),
            });
        }
        self.prepare(nx, ny);
        let transform = self.transform.as_mut().expect("prepared above");
        let field = &mut self.field;
        let [output_w, cost, tmp_output, ..] = &mut self.spectra;

        // The patch side: its weights, weighted squared norms and weighted channels, transformed
        // once per patch when the caller names it with a key (a synthesis searches the same
        // exemplar against a changing output at every placement).
        let cached = patch_key.is_some()
            && self
                .patch_cache
                .as_ref()
                .is_some_and(|c| c.key == patch_key && (c.nx, c.ny) == (nx, ny));
        if !cached {
            let channels = patch.image.channels();
            let mut spectra = vec![vec![Complex::default(); (nx / 2 + 1) * ny]; 2 + channels];
            patch.scatter(field, nx, ny, |_, w| w);
            transform.forward(field, &mut spectra[0]);
            patch.scatter(field, nx, ny, |pixel, w| w * squared_norm(pixel));
            transform.forward(field, &mut spectra[1]);
            for channel in 0..channels {
                patch.scatter(field, nx, ny, |pixel, w| w * f64::from(pixel[channel]));
                transform.forward(field, &mut spectra[2 + channel]);
            }
            self.patch_cache = Some(PatchSpectra {
                key: patch_key,
                nx,
                ny,
                spectra,
            });
        }
        let patch_spectra = &self.patch_cache.as_ref().expect("filled above").spectra;
        let (patch_w, patch_squares) = (&patch_spectra[0], &patch_spectra[1]);

        output.scatter(field, nx, ny, |_, w| w);
        transform.forward(field, output_w);
        for ((c, &o), &p) in cost.iter_mut().zip(output_w.iter()).zip(patch_w.iter()) {
            *c = o * p.conj();
        }
        transform.inverse(cost, field);
        let mut areas = read_map(field, nx, ny, map_width, map_height, first_offset);

        output.scatter(field, nx, ny, |pixel, w| w * squared_norm(pixel));
        transform.forward(field, tmp_output);
        for ((c, &o), &p) in cost.iter_mut().zip(tmp_output.iter()).zip(patch_w.iter()) {
            *c = o * p.conj();
        }
        for ((c, &o), &p) in cost
            .iter_mut()
            .zip(output_w.iter())
            .zip(patch_squares.iter())
        {
            *c += o * p.conj();
        }
        for channel in 0..output.image.channels() {
            output.scatter(field, nx, ny, |pixel, w| w * f64::from(pixel[channel]));
            transform.forward(field, tmp_output);
            for ((c, &o), &p) in cost
                .iter_mut()
                .zip(tmp_output.iter())
                .zip(patch_spectra[2 + channel].iter())
            {
                *c -= 2.0 * o * p.conj();
            }
        }
        transform.inverse(cost, field);
        let mut costs = read_map(field, nx, ny, map_width, map_height, first_offset);

        for (cost, area) in costs.iter_mut().zip(areas.iter_mut()) {
            if *area < MIN_AREA {
                *area = 0.0;
                *cost = 0.0;
            }
            // Rounding can leave a perfect match slightly below zero.
            *cost = cost.max(0.0);
        }
        Ok(SsdMap {
            width: map_width,
            height: map_height,
            first_offset,
            costs,
            areas,
        })
    }

    /// Plans the transforms for an `nx` x `ny` grid (the planners cache the plans) and sizes the
    /// buffers.
    fn prepare(&mut self, nx: usize, ny: usize) {
        if self
            .transform
            .as_ref()
            .is_none_or(|t| (t.nx, t.ny) != (nx, ny))
        {
            self.transform = Some(Transform2d::new(
                nx,
                ny,
                &mut self.real_planner,
                &mut self.complex_planner,
            ));
        }
        self.field.resize(nx * ny, 0.0);
        for spectrum in &mut self.spectra {
            spectrum.resize((nx / 2 + 1) * ny, Complex::default());
        }
    }
}

/// An image with its per-pixel weights, checked.
struct Weighted<'a> {
    image: &'a Image,
    weights: Option<&'a [f32]>,
}

impl<'a> Weighted<'a> {
    /// `names`: how errors call the image and its weights.
    fn new(
        image: &'a Image,
        weights: Option<&'a [f32]>,
        names: (&'static str, &'static str),
    ) -> Result<Self> {
        let weighted = Weighted { image, weights };
        if let Some(weights) = weights
            && weights.len() != image.pixel_count()
        {
            return Err(Error::LengthMismatch {
                what: names.1,
                expected: image.pixel_count(),
                actual: weights.len(),
            });
        }
        for (i, pixel) in image.data().chunks_exact(image.channels()).enumerate() {
            let weight = weighted.weight(i);
            let problem = if !weight.is_finite() || weight < 0.0 {
                Some(format!(
                    "weight {weight} at pixel {i}; weights must be finite and non-negative"
                ))
            } else if weight > 0.0 && pixel.iter().any(|v| !v.is_finite()) {
                Some(format!("pixel {i} has a value that is not finite"))
            } else {
                None
            };
            if let Some(reason) = problem {
                return Err(Error::InvalidParameter {
                    name: names.0,
                    reason,
                });
            }
        }
        Ok(weighted)
    }

    #[inline]
    fn weight(&self, pixel: usize) -> f32 {
        self.weights.map_or(1.0, |w| w[pixel])
    }

    /// Fills the `nx` x `ny` field with `value(pixel, weight)` at each pixel of weight > 0, zero
    /// elsewhere. Coordinates wrap, so a patch larger than a periodic output folds onto it; every
    /// term of the cost is linear in the patch's values, so folding keeps the sums exact.
    fn scatter(&self, field: &mut [f64], nx: usize, ny: usize, value: impl Fn(&[f32], f64) -> f64) {
        field.fill(0.0);
        let (width, channels) = (self.image.width(), self.image.channels());
        for (y, row) in self.image.data().chunks_exact(width * channels).enumerate() {
            let base = (y % ny) * nx;
            for (x, pixel) in row.chunks_exact(channels).enumerate() {
                let weight = self.weight(y * width + x);
                if weight > 0.0 {
                    field[base + x % nx] += value(pixel, f64::from(weight));
                }
            }
        }
    }
}

/// Reads the map of translations out of a correlation on the `nx` x `ny` torus, where translation
/// `t` sits at `t mod n`, and undoes the transform's scale.
fn read_map(
    field: &[f64],
    nx: usize,
    ny: usize,
    width: usize,
    height: usize,
    first: (isize, isize),
) -> Vec<f32> {
    let scale = 1.0 / (nx * ny) as f64;
    let mut map = Vec::with_capacity(width * height);
    for j in 0..height {
        let y = (first.1 + j as isize).rem_euclid(ny as isize) as usize;
        for i in 0..width {
            let x = (first.0 + i as isize).rem_euclid(nx as isize) as usize;
            map.push((field[y * nx + x] * scale) as f32);
        }
    }
    map
}

/// `|v|^2` of one pixel, summed over its channels.
fn squared_norm(pixel: &[f32]) -> f64 {
    pixel.iter().map(|&v| f64::from(v) * f64::from(v)).sum()
}

/// The smallest size `>= n` whose only prime factors are 2, 3 and 5, where FFTs are fastest.
fn smooth_size(n: usize) -> usize {
    (n.max(1)..)
        .find(|&m| {
            let mut rest = m;
            for p in [2, 3, 5] {
                while rest.is_multiple_of(p) {
                    rest /= p;
                }
            }
            rest == 1
        })
        .expect("smooth numbers are unbounded")
}

/// A 2-D real FFT: real transforms along the rows, then complex transforms along the columns.
/// The spectrum is stored transposed (`spectrum[kx * ny + y]`), so that each column transform
/// reads contiguous memory; products of spectra do not care about the layout.
struct Transform2d {
    nx: usize,
    ny: usize,
    rows_forward: Arc<dyn RealToComplex<f64>>,
    rows_inverse: Arc<dyn ComplexToReal<f64>>,
    columns_forward: Arc<dyn Fft<f64>>,
    columns_inverse: Arc<dyn Fft<f64>>,
    row: Vec<Complex<f64>>,
    scratch: Vec<Complex<f64>>,
}

impl Transform2d {
    fn new(
        nx: usize,
        ny: usize,
        real_planner: &mut RealFftPlanner<f64>,
        complex_planner: &mut FftPlanner<f64>,
    ) -> Self {
        let rows_forward = real_planner.plan_fft_forward(nx);
        let rows_inverse = real_planner.plan_fft_inverse(nx);
        let columns_forward = complex_planner.plan_fft_forward(ny);
        let columns_inverse = complex_planner.plan_fft_inverse(ny);
        let scratch_len = rows_forward
            .get_scratch_len()
            .max(rows_inverse.get_scratch_len())
            .max(columns_forward.get_inplace_scratch_len())
            .max(columns_inverse.get_inplace_scratch_len());
        Transform2d {
            nx,
            ny,
            rows_forward,
            rows_inverse,
            columns_forward,
            columns_inverse,
            row: vec![Complex::default(); nx / 2 + 1],
            scratch: vec![Complex::default(); scratch_len],
        }
    }

    /// `field` (row-major, `nx * ny`, overwritten) to its unnormalised spectrum.
    fn forward(&mut self, field: &mut [f64], spectrum: &mut [Complex<f64>]) {
        let ny = self.ny;
        for (y, row) in field.chunks_exact_mut(self.nx).enumerate() {
            self.rows_forward
                .process_with_scratch(row, &mut self.row, &mut self.scratch)
                .expect("buffer lengths match the plan");
            for (k, &value) in self.row.iter().enumerate() {
                spectrum[k * ny + y] = value;
            }
        }
        self.columns_forward
            .process_with_scratch(spectrum, &mut self.scratch);
    }

    /// The spectrum (overwritten) back to `field`, scaled by `nx * ny`.
    fn inverse(&mut self, spectrum: &mut [Complex<f64>], field: &mut [f64]) {
        let ny = self.ny;
        self.columns_inverse
            .process_with_scratch(spectrum, &mut self.scratch);
        let last = self.row.len() - 1;
        for (y, row) in field.chunks_exact_mut(self.nx).enumerate() {
            for (k, value) in self.row.iter_mut().enumerate() {
                *value = spectrum[k * ny + y];
            }
            // The spectrum of a real row has real DC and Nyquist terms; what rounding leaves in
            // their imaginary parts is noise, which the real inverse refuses.
            self.row[0].im = 0.0;
            if self.nx.is_multiple_of(2) {
                self.row[last].im = 0.0;
            }
            self.rows_inverse
                .process_with_scratch(&mut self.row, row, &mut self.scratch)
                .expect("buffer lengths match the plan");
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Rng;

    /// The obvious SSD: every translation, every patch pixel. Returns `(costs, areas)` laid out
    /// like [`SsdMap`].
    fn direct_ssd(
        output: &Image,
        output_weights: Option<&[f32]>,
        patch: &Image,
        patch_weights: Option<&[f32]>,
        boundary: Boundary,
    ) -> (Vec<f64>, Vec<f64>) {
        let (ow, oh) = (output.width() as isize, output.height() as isize);
        let (pw, ph) = (patch.width() as isize, patch.height() as isize);
        let (xs, ys) = match boundary {
            Boundary::Open => (1 - pw..ow, 1 - ph..oh),
            Boundary::Periodic => (0..ow, 0..oh),
        };
        let weight = |w: Option<&[f32]>, i: usize| f64::from(w.map_or(1.0, |w| w[i]));
        let (mut costs, mut areas) = (Vec::new(), Vec::new());
        for ty in ys {
            for tx in xs.clone() {
                let (mut cost, mut area) = (0.0, 0.0);
                for v in 0..ph {
                    for u in 0..pw {
                        let (mut x, mut y) = (u + tx, v + ty);
                        if boundary == Boundary::Periodic {
                            (x, y) = (x.rem_euclid(ow), y.rem_euclid(oh));
                        } else if x < 0 || y < 0 || x >= ow || y >= oh {
                            continue;
                        }
                        let o = (y * ow + x) as usize;
                        let p = (v * pw + u) as usize;
                        let w = weight(output_weights, o) * weight(patch_weights, p);
                        if w == 0.0 {
                            continue;
                        }
                        area += w;
                        let (a, b) = (
                            output.pixel(x as usize, y as usize),
                            patch.pixel(u as usize, v as usize),
                        );
                        cost += w * a
                            .iter()
                            .zip(b)
                            .map(|(&a, &b)| f64::from(a - b).powi(2))
                            .sum::<f64>();
                    }
                }
                costs.push(cost);
                areas.push(area);
            }
        }
        (costs, areas)
    }

    fn random_image(rng: &mut Rng, width: usize, height: usize, channels: usize) -> Image {
        Image::from_fn(width, height, channels, |_, _, _| rng.next_f32()).unwrap()
    }

    /// Binary masks (a filled region with holes), soft weights, or none.
    fn random_weights(rng: &mut Rng, pixels: usize, kind: u32) -> Option<Vec<f32>> {
        match kind {
            0 => None,
            1 => Some((0..pixels).map(|_| f32::from(rng.below(3) > 0)).collect()),
            _ => Some(
                (0..pixels)
                    .map(|_| {
                        if rng.below(4) == 0 {
                            0.0
                        } else {
                            rng.next_f32()
                        }
                    })
                    .collect(),
            ),
        }
    }

    fn assert_matches_direct(rng: &mut Rng, boundary: Boundary, rounds: usize, max_side: usize) {
        let mut search = SsdSearch::new();
        for round in 0..rounds {
            let channels = 1 + rng.index(4);
            let (ow, oh) = (1 + rng.index(max_side), 1 + rng.index(max_side));
            let (pw, ph) = (1 + rng.index(max_side), 1 + rng.index(max_side));
            let output = random_image(rng, ow, oh, channels);
            let patch = random_image(rng, pw, ph, channels);
            let kinds = (rng.below(3), rng.below(3));
            let output_weights = random_weights(rng, ow * oh, kinds.0);
            let patch_weights = random_weights(rng, pw * ph, kinds.1);
            let (ow_ref, pw_ref) = (output_weights.as_deref(), patch_weights.as_deref());
            let map = search
                .search(&output, ow_ref, &patch, pw_ref, boundary)
                .unwrap();
            let (costs, areas) = direct_ssd(&output, ow_ref, &patch, pw_ref, boundary);
            assert_eq!(map.costs().len(), costs.len(), "round {round}");
            assert_eq!(map.width() * map.height(), costs.len());
            for (index, (&cost, &area)) in costs.iter().zip(&areas).enumerate() {
                let (got_cost, got_area) =
                    (f64::from(map.costs()[index]), f64::from(map.areas()[index]));
                let context = format!(
                    "round {round}, {boundary:?}, {ow}x{oh} output, {pw}x{ph} patch, {channels} channels, offset {:?}",
                    map.offset(index)
                );
                assert!(
                    (got_area - area).abs() <= 1e-5 * (1.0 + area),
                    "area {got_area} vs {area}: {context}"
                );
                assert!(
                    (got_cost - cost).abs() <= 1e-5 * (1.0 + cost),
                    "cost {got_cost} vs {cost}: {context}"
                );
            }
        }
    }

    #[test]
    fn open_boundary_matches_direct_ssd() {
        assert_matches_direct(&mut Rng::new(11), Boundary::Open, 150, 13);
    }

    #[test]
    fn periodic_boundary_matches_direct_ssd() {
        // Patches may be larger than the output here: they fold onto the torus.
        assert_matches_direct(&mut Rng::new(12), Boundary::Periodic, 150, 13);
    }

    #[test]
    fn larger_images_match_direct_ssd_at_sampled_offsets() {
        let mut rng = Rng::new(13);
        let output = random_image(&mut rng, 61, 47, 3);
        let patch = random_image(&mut rng, 23, 31, 3);
        let weights = random_weights(&mut rng, 61 * 47, 1).unwrap();
        for boundary in [Boundary::Open, Boundary::Periodic] {
            let map = ssd_map(&output, Some(&weights), &patch, None, boundary).unwrap();
            let (costs, areas) = direct_ssd(&output, Some(&weights), &patch, None, boundary);
            for index in (0..costs.len()).step_by(7) {
                let got = f64::from(map.costs()[index]);
                assert!(
                    (got - costs[index]).abs() <= 1e-5 * (1.0 + costs[index]),
                    "{boundary:?} {index}"
                );
                assert_eq!(
                    f64::from(map.areas()[index]),
                    areas[index],
                    "binary areas are whole numbers"
                );
            }
        }
    }

    #[test]
    fn a_patch_cut_from_the_output_matches_exactly_where_it_came_from() {
        let mut rng = Rng::new(14);
        let output = random_image(&mut rng, 40, 30, 3);
        let patch = output.crop(9, 5, 16, 12).unwrap();
        for boundary in [Boundary::Open, Boundary::Periodic] {
            let map = ssd_map(&output, None, &patch, None, boundary).unwrap();
            let (cost, area) = map.get(9, 5).unwrap();
            assert!(cost < 1e-4, "{boundary:?}: {cost}");
            assert_eq!(area, 16.0 * 12.0);
            let (best, _) = map
                .costs()
                .iter()
                .enumerate()
                .filter(|&(i, _)| map.areas()[i] == 16.0 * 12.0)
                .min_by(|a, b| a.1.total_cmp(b.1))
                .unwrap();
            assert_eq!(map.offset(best), (9, 5));
        }
    }

    #[test]
    fn map_layout_and_overlap_areas() {
        let output = Image::new(5, 4, 1).unwrap();
        let patch = Image::new(3, 2, 1).unwrap();
        let open = ssd_map(&output, None, &patch, None, Boundary::Open).unwrap();
        assert_eq!((open.width(), open.height()), (7, 5));
        assert_eq!(open.first_offset(), (-2, -1));
        assert_eq!(open.offset(0), (-2, -1));
        assert_eq!(open.offset(7 * 5 - 1), (4, 3));
        assert_eq!(
            open.get(-2, -1),
            Some((0.0, 1.0)),
            "one corner pixel overlaps"
        );
        assert_eq!(open.get(1, 1), Some((0.0, 6.0)), "whole patch inside");
        assert_eq!(open.get(4, 3), Some((0.0, 1.0)));
        assert_eq!(open.get(5, 0), None);
        assert_eq!(open.get(-3, 0), None);
        let periodic = ssd_map(&output, None, &patch, None, Boundary::Periodic).unwrap();
        assert_eq!(
            (periodic.width(), periodic.height(), periodic.first_offset()),
            (5, 4, (0, 0))
        );
        assert!(
            periodic.areas().iter().all(|&a| a == 6.0),
            "the whole patch always overlaps"
        );
    }

    #[test]
    fn no_overlap_means_zero_area_and_zero_cost() {
        let output = Image::from_fn(6, 6, 2, |x, y, c| (x + y + c) as f32).unwrap();
        let patch = Image::from_fn(3, 3, 2, |_, _, _| 0.5).unwrap();
        // Only the left half of the output is filled.
        let weights: Vec<f32> = (0..36).map(|i| f32::from(i % 6 < 3)).collect();
        let map = ssd_map(&output, Some(&weights), &patch, None, Boundary::Open).unwrap();
        let (cost, area) = map.get(4, 2).unwrap();
        assert_eq!((cost, area), (0.0, 0.0));
        assert!(map.costs().iter().all(|&c| c >= 0.0));
    }

    #[test]
    fn unfilled_pixels_are_not_read_but_filled_ones_must_be_finite() {
        let mut output = Image::from_fn(4, 4, 1, |x, _, _| x as f32 / 4.0).unwrap();
        output.pixel_mut(3, 3)[0] = f32::NAN;
        let patch = Image::from_fn(2, 2, 1, |_, _, _| 0.25).unwrap();
        let mut weights = vec![1.0; 16];
        weights[15] = 0.0;
        let map = ssd_map(&output, Some(&weights), &patch, None, Boundary::Open).unwrap();
        assert!(map.costs().iter().all(|c| c.is_finite()));
        let err = ssd_map(&output, None, &patch, None, Boundary::Open).unwrap_err();
        assert!(err.to_string().contains("not finite"), "{err}");
    }

    #[test]
    fn bad_input_is_a_named_error() {
        let grey = Image::new(4, 4, 1).unwrap();
        let colour = Image::new(2, 2, 3).unwrap();
        let err = ssd_map(&grey, None, &colour, None, Boundary::Open).unwrap_err();
        assert!(err.to_string().contains("3 channels"), "{err}");
        let err = ssd_map(&grey, Some(&[1.0; 15]), &grey, None, Boundary::Open).unwrap_err();
        assert_eq!(
            err,
            Error::LengthMismatch {
                what: "output weights",
                expected: 16,
                actual: 15
            }
        );
        let mut weights = [1.0f32; 16];
        weights[3] = -1.0;
        let err = ssd_map(&grey, None, &grey, Some(&weights), Boundary::Open).unwrap_err();
        assert!(
            matches!(err, Error::InvalidParameter { name: "patch", .. }),
            "{err}"
        );
        weights[3] = f32::NAN;
        assert!(ssd_map(&grey, Some(&weights), &grey, None, Boundary::Periodic).is_err());
        let wide = Image::new(4000, 1, 1).unwrap();
        let tall = Image::new(1, 4000, 1).unwrap();
        let big = Image::new(1500, 1500, 1).unwrap();
        let err = ssd_map(&big, None, &big, None, Boundary::Open).unwrap_err();
        assert!(err.to_string().contains("FFT search"), "{err}");
        assert!(ssd_map(&wide, None, &tall, None, Boundary::Open).is_err());
    }

    #[test]
    fn a_reused_search_gives_the_same_maps_as_a_fresh_one() {
        let mut rng = Rng::new(15);
        let mut search = SsdSearch::new();
        for (size, boundary) in [
            (9, Boundary::Open),
            (14, Boundary::Periodic),
            (9, Boundary::Open),
        ] {
            let output = random_image(&mut rng, size, size + 3, 2);
            let patch = random_image(&mut rng, 5, 4, 2);
            let reused = search
                .search(&output, None, &patch, None, boundary)
                .unwrap();
            let fresh = ssd_map(&output, None, &patch, None, boundary).unwrap();
            assert_eq!(reused, fresh);
        }
    }

    #[test]
    fn a_keyed_search_reuses_the_patch_and_matches_a_fresh_one() {
        let mut rng = Rng::new(17);
        let mut search = SsdSearch::new();
        let patches = [
            random_image(&mut rng, 5, 4, 3),
            random_image(&mut rng, 5, 4, 3),
        ];
        // Keys 0, 0, 1, 0 (recomputed when the key changes back), with changing outputs and sizes.
        for (key, size, boundary) in [
            (0, 9, Boundary::Open),
            (0, 9, Boundary::Open),
            (1, 9, Boundary::Open),
            (0, 12, Boundary::Periodic),
        ] {
            let output = random_image(&mut rng, size, size + 2, 3);
            let weights = random_weights(&mut rng, size * (size + 2), 1).unwrap();
            let patch = &patches[key as usize];
            let keyed = search
                .search_keyed(&output, Some(&weights), patch, None, boundary, Some(key))
                .unwrap();
            let fresh = ssd_map(&output, Some(&weights), patch, None, boundary).unwrap();
            assert_eq!(keyed, fresh);
        }
    }

    /// A measurement, not a check: `cargo test --release --lib -- --ignored --nocapture fft_ssd_timing`.
    #[test]
    #[ignore = "a timing report; run with --release --ignored --nocapture"]
    fn fft_ssd_timing() {
        let mut rng = Rng::new(16);
        let mut search = SsdSearch::new();
        for (out_side, patch_side) in [(128, 64), (256, 128), (512, 256)] {
            let output = random_image(&mut rng, out_side, out_side, 3);
            let patch = random_image(&mut rng, patch_side, patch_side, 3);
            let weights = random_weights(&mut rng, out_side * out_side, 1).unwrap();
            for boundary in [Boundary::Open, Boundary::Periodic] {
                search
                    .search(&output, Some(&weights), &patch, None, boundary)
                    .unwrap();
                let started = std::time::Instant::now();
                let map = search
                    .search(&output, Some(&weights), &patch, None, boundary)
                    .unwrap();
                println!(
                    "{out_side}x{out_side} output, {patch_side}x{patch_side} patch, RGB, {boundary:?}: \
                     {} translations in {:.1} ms",
                    map.costs().len(),
                    started.elapsed().as_secs_f64() * 1e3
                );
            }
        }
    }

    #[test]
    fn smooth_sizes_have_only_small_prime_factors() {
        let sizes: Vec<usize> = [0, 1, 7, 11, 13, 97, 128, 129].map(smooth_size).to_vec();
        assert_eq!(sizes, [1, 1, 8, 12, 15, 100, 128, 135]);
    }
}
