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

#[cfg(test)]
mod tests;
mod transform;
mod volume;

use transform::Transform;
pub use volume::{
    MAX_VOLUME_TRANSFORM_VALUES, VolumeRange, VolumeSsdMap, VolumeView, volume_range_transform_size,
    volume_search_bytes, volume_ssd_map, volume_ssd_map_range, volume_transform_size,
};

use crate::solvers::fft::{Complex, correlate_spectra, smooth_size};

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

/// The translations a [`SsdSearch::search_range`] computes: `count` of them from `first`, along x
/// and y.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct OffsetRange {
    pub first: (isize, isize),
    pub count: (usize, usize),
}

/// Overlaps whose total weight is below this count as no overlap: the transform leaves noise of
/// about `1e-12` where the true area is zero, and `C / A` there would be meaningless.
pub const MIN_AREA: f32 = 1e-6;

/// The largest transform, in values (`2048 x 2048`): five spectra of it already take 170 MB.
pub const MAX_TRANSFORM_VALUES: usize = 1 << 22;

/// The size of the transform a search of a `pw` x `ph` patch over a `ow` x `oh` output uses: at
/// most [`MAX_TRANSFORM_VALUES`] values are allowed, so callers can refuse a size up front.
#[must_use]
pub fn transform_size(
    (ow, oh): (usize, usize),
    (pw, ph): (usize, usize),
    boundary: Boundary,
) -> (usize, usize) {
    match boundary {
        // Padding to at least `ow + pw - 1` keeps the circular correlation from wrapping; an even
        // width lets the row transforms run at half length.
        Boundary::Open => (
            2 * smooth_size((ow + pw - 1).div_ceil(2)),
            smooth_size(oh + ph - 1),
        ),
        Boundary::Periodic => (ow, oh),
    }
}

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
    transform: Option<Transform>,
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
        let (ow, oh) = (output.width(), output.height());
        let (pw, ph) = (patch.width(), patch.height());
        let (nx, ny) = transform_size((ow, oh), (pw, ph), boundary);
        let (map_width, map_height, first_offset) = match boundary {
            Boundary::Open => (ow + pw - 1, oh + ph - 1, (1 - pw as isize, 1 - ph as isize)),
            Boundary::Periodic => (ow, oh, (0, 0)),
        };
        let map = (map_width, map_height, first_offset);
        self.correlate(
            (output, output_weights),
            (patch, patch_weights),
            (nx, ny),
            map,
            patch_key,
        )
    }

    /// Like [`SsdSearch::search_keyed`] with [`Boundary::Open`], for the translations of `range`
    /// only: `first` and `count` along x and y (any of them, inside the output or not). The
    /// transform needs to be only as large as the offsets and the patch span together, not the
    /// output plus the patch: a graph-cut placement, whose candidates lie in a window of `2 pw -
    /// region` around the error region, transforms about 180 values a side instead of 300.
    ///
    /// A circular correlation of length `n` is the linear one at offset `t` when no patch pixel
    /// `u` wraps onto the output's data: `t + u` below 0 must land at `n + t + u >= ow`, and
    /// above `n - 1` cannot happen, so `n >= ow - t_min` and `n >= t_max + pw` (and `n >= ow` to
    /// hold the data).
    pub fn search_range(
        &mut self,
        output: (&Image, Option<&[f32]>),
        patch: (&Image, Option<&[f32]>),
        range: OffsetRange,
        patch_key: Option<u64>,
    ) -> Result<SsdMap> {
        let (ow, oh) = (output.0.width(), output.0.height());
        let (pw, ph) = (patch.0.width(), patch.0.height());
        let (cx, cy) = range.count;
        if cx == 0 || cy == 0 {
            return Err(Error::InvalidParameter {
                name: "offset range",
                reason: format!("is empty ({cx}x{cy} offsets)"),
            });
        }
        let nx = 2 * smooth_size(range_length(ow, range.first.0, cx, pw).div_ceil(2));
        let ny = smooth_size(range_length(oh, range.first.1, cy, ph));
        self.correlate(output, patch, (nx, ny), (cx, cy, range.first), patch_key)
    }

    /// The search proper: `nx` x `ny` transforms, read out as a `map_width` x `map_height` map of
    /// translations from `first_offset`.
    fn correlate(
        &mut self,
        (output, output_weights): (&Image, Option<&[f32]>),
        (patch, patch_weights): (&Image, Option<&[f32]>),
        (nx, ny): (usize, usize),
        (map_width, map_height, first_offset): (usize, usize, (isize, isize)),
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
        correlate_spectra(cost, output_w, patch_w, 1.0, false);
        transform.inverse(cost, field);
        let mut areas = read_map(field, nx, ny, map_width, map_height, first_offset);

        output.scatter(field, nx, ny, |pixel, w| w * squared_norm(pixel));
        transform.forward(field, tmp_output);
        correlate_spectra(cost, tmp_output, patch_w, 1.0, false);
        correlate_spectra(cost, output_w, patch_squares, 1.0, true);
        for channel in 0..output.image.channels() {
            output.scatter(field, nx, ny, |pixel, w| w * f64::from(pixel[channel]));
            transform.forward(field, tmp_output);
            correlate_spectra(cost, tmp_output, &patch_spectra[2 + channel], -2.0, true);
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

    /// Plans the transforms for an `nx` x `ny` grid (planned again only when the size changes) and sizes the
    /// buffers.
    fn prepare(&mut self, nx: usize, ny: usize) {
        if self
            .transform
            .as_ref()
            .is_none_or(|t| (t.nx, t.ny) != (nx, ny))
        {
            self.transform = Some(Transform::new(nx, ny));
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

/// The shortest circular correlation along one axis that holds the linear one at the `count`
/// offsets from `first` of a patch of length `patch` over data of length `len` (see
/// [`SsdSearch::search_range`]).
fn range_length(len: usize, first: isize, count: usize, patch: usize) -> usize {
    let last = first + count as isize - 1;
    let below = (len as isize - first.min(0)).max(len as isize);
    below.max(last + patch as isize).max(1) as usize
}

/// `|v|^2` of one pixel, summed over its channels.
fn squared_norm(pixel: &[f32]) -> f64 {
    pixel.iter().map(|&v| f64::from(v) * f64::from(v)).sum()
}
