//! Neighbourhoods as vectors: a multi-channel feature map, the set of all `w` x `w` neighbourhoods
//! of an exemplar (stored as locations, not copies), and the Gaussian-weighted squared distance
//! that both the M-step search and the texture energy use.

/// A dense multi-channel map (`dims` values per pixel, interleaved): colour, or colour plus
/// scaled gradients when the gradient energy is on.
#[derive(Debug, Clone, PartialEq)]
pub struct FeatureMap {
    pub width: usize,
    pub height: usize,
    pub dims: usize,
    pub data: Vec<f32>,
}

impl FeatureMap {
    /// Values of row `y` from column `x`, `len` pixels long.
    #[inline]
    #[must_use]
    pub fn row(&self, x: usize, y: usize, len: usize) -> &[f32] {
        let start = (y * self.width + x) * self.dims;
        &self.data[start..start + len * self.dims]
    }
}

/// Top-left corner of a neighbourhood in the exemplar.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Pos {
    pub x: u32,
    pub y: u32,
}

impl Pos {
    #[must_use]
    pub fn new(x: usize, y: usize) -> Self {
        Pos {
            x: x as u32,
            y: y as u32,
        }
    }
}

/// Per-pixel Gaussian fall-off inside a `size` x `size` neighbourhood (Kwatra et al. 2005, end of
/// section 3.1: pixels near the centre have more bearing on the texture), expanded over `dims`
/// values per pixel so that distance loops multiply element by element.
///
/// The paper gives no width; sigma = size / 3 keeps the border pixels at about 0.42 of the centre
/// weight along each axis (0.18 in the corners): the overlap still ties neighbouring
/// neighbourhoods together, while each neighbourhood's centre dominates its own pixels.
#[must_use]
pub fn gaussian_falloff(size: usize, dims: usize) -> Vec<f32> {
    let sigma = size as f32 / 3.0;
    let centre = (size as f32 - 1.0) / 2.0;
    let mut weights = Vec::with_capacity(size * size * dims);
    for y in 0..size {
        for x in 0..size {
            let (dx, dy) = (x as f32 - centre, y as f32 - centre);
            let g = crate::core::math::expf(-(dx * dx + dy * dy) / (2.0 * sigma * sigma));
            weights.extend(std::iter::repeat_n(g, dims));
        }
    }
    weights
}

/// `sum g_k (a_k - b_k)^2`, written with eight independent accumulators so that the compiler turns
/// it into SIMD lanes (a single running sum would force sequential float additions).
#[inline]
#[must_use]
pub fn weighted_ssd(a: &[f32], b: &[f32], g: &[f32]) -> f32 {
    debug_assert!(a.len() == b.len() && a.len() == g.len());
    let g = &g[..a.len()];
    ssd_weighted_by(a, b, |k| g[k])
}

/// `sum (g_k G_k) (a_k - b_k)^2`: [`weighted_ssd`] under the weights `g` scaled value by value
/// by the gains `G` (a soft constraint's `1 + lambda m` per pixel, read in place), the products
/// formed as a query's own weights would be.
#[inline]
#[must_use]
pub fn gained_weighted_ssd(a: &[f32], b: &[f32], g: &[f32], gains: &[f32]) -> f32 {
    debug_assert!(a.len() == b.len() && a.len() == g.len() && a.len() == gains.len());
    let (g, gains) = (&g[..a.len()], &gains[..a.len()]);
    ssd_weighted_by(a, b, |k| g[k] * gains[k])
}

/// The sum of both: eight accumulators over chunks of 8, then the tail, with the weight of
/// value `k` given by `weight(k)`.
#[inline(always)]
fn ssd_weighted_by(a: &[f32], b: &[f32], weight: impl Fn(usize) -> f32) -> f32 {
    let mut acc = [0.0f32; 8];
    let chunks = a.len() / 8 * 8;
    for (c, (ca, cb)) in a[..chunks]
        .chunks_exact(8)
        .zip(b[..chunks].chunks_exact(8))
        .enumerate()
    {
        for (k, sum) in acc.iter_mut().enumerate() {
            let d = ca[k] - cb[k];
            *sum += weight(c * 8 + k) * d * d;
        }
    }
    let mut sum = (acc[0] + acc[4]) + (acc[1] + acc[5]) + ((acc[2] + acc[6]) + (acc[3] + acc[7]));
    for k in chunks..a.len() {
        let d = a[k] - b[k];
        sum += weight(k) * d * d;
    }
    sum
}

/// [`weighted_ssd`] (or [`gained_weighted_ssd`]) of exactly `N` values, `N` a multiple of 8:
/// the same sums in the same order, fully unrolled.
#[inline(always)]
fn fixed_weighted_ssd<const N: usize>(
    a: &[f32],
    b: &[f32],
    g: &[f32],
    gains: Option<&[f32]>,
) -> f32 {
    let (Ok(a), Ok(b), Ok(g)) = (
        <&[f32; N]>::try_from(a),
        <&[f32; N]>::try_from(b),
        <&[f32; N]>::try_from(g),
    ) else {
        return match gains {
            Some(gains) => gained_weighted_ssd(a, b, g, gains),
            None => weighted_ssd(a, b, g),
        };
    };
    match gains.map(<&[f32; N]>::try_from) {
        None => lanes::weighted_ssd(a, b, g, None),
        Some(Ok(gains)) => lanes::weighted_ssd(a, b, g, Some(gains)),
        Some(Err(_)) => gained_weighted_ssd(a, b, g, gains.unwrap_or_default()),
    }
}

/// The eight accumulators of [`weighted_ssd`] as two 128-bit vectors where wasm has them: the
/// compiler's own vectorisation of the scalar loop shuffled lanes at every chunk.
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
mod lanes {
    use core::arch::wasm32::{
        f32x4_add, f32x4_extract_lane, f32x4_mul, f32x4_splat, f32x4_sub, v128, v128_load,
    };

    #[inline(always)]
    fn load(values: &[f32], at: usize) -> v128 {
        let four = &values[at..at + 4];
        // SAFETY: `four` is four in-bounds f32s; v128_load has no alignment requirement.
        unsafe { v128_load(four.as_ptr().cast::<v128>()) }
    }

    #[inline(always)]
    pub fn weighted_ssd<const N: usize>(
        a: &[f32; N],
        b: &[f32; N],
        g: &[f32; N],
        gains: Option<&[f32; N]>,
    ) -> f32 {
        let weight = |at: usize| match gains {
            Some(gains) => f32x4_mul(load(g, at), load(gains, at)),
            None => load(g, at),
        };
        let (mut low, mut high) = (f32x4_splat(0.0), f32x4_splat(0.0));
        for c in 0..N / 8 {
            let (i, j) = (c * 8, c * 8 + 4);
            let d = f32x4_sub(load(a, i), load(b, i));
            low = f32x4_add(low, f32x4_mul(f32x4_mul(weight(i), d), d));
            let d = f32x4_sub(load(a, j), load(b, j));
            high = f32x4_add(high, f32x4_mul(f32x4_mul(weight(j), d), d));
        }
        let s = f32x4_add(low, high);
        (f32x4_extract_lane::<0>(s) + f32x4_extract_lane::<1>(s))
            + (f32x4_extract_lane::<2>(s) + f32x4_extract_lane::<3>(s))
    }
}

#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
mod lanes {
    #[inline(always)]
    pub fn weighted_ssd<const N: usize>(
        a: &[f32; N],
        b: &[f32; N],
        g: &[f32; N],
        gains: Option<&[f32; N]>,
    ) -> f32 {
        let mut acc = [0.0f32; 8];
        for c in 0..N / 8 {
            for (k, sum) in acc.iter_mut().enumerate() {
                let i = c * 8 + k;
                let d = a[i] - b[i];
                let weight = gains.map_or(g[i], |gains| g[i] * gains[i]);
                *sum += weight * d * d;
            }
        }
        (acc[0] + acc[4]) + (acc[1] + acc[5]) + ((acc[2] + acc[6]) + (acc[3] + acc[7]))
    }
}

/// A query read where it lies instead of copied: row `dy` of its values is
/// `values[dy * stride..]` (a feature map `stride / dims` pixels wide), and its weights are the
/// space's fall-off scaled by `gains` where given (laid out like `values`).
#[derive(Debug, Clone, Copy)]
pub struct InPlace<'a> {
    pub values: &'a [f32],
    pub gains: Option<&'a [f32]>,
    pub stride: usize,
}

/// All `size` x `size` neighbourhoods of an exemplar feature map, addressed by top-left corner.
///
/// By default a neighbourhood's vector is read from the feature map where it lies (no copies).
/// [`Neighbourhoods::transformed`] instead stores every neighbourhood's image under a fixed
/// linear map (e.g. a wavelet transform), computed once, with per-value weights of its own:
/// the distance is then the weighted distance between transformed vectors, and every search
/// runs unchanged on them (the queries must be transformed the same way).
#[derive(Debug, Clone)]
pub struct Neighbourhoods {
    exemplar: FeatureMap,
    size: usize,
    weights: Vec<f32>,
    /// Transformed vectors, `vector_len()` each, in scan order of [`Neighbourhoods::pos_of`];
    /// empty when vectors are read from the feature map.
    transformed: Vec<f32>,
    /// The feature map holds this many copies of the exemplar stacked vertically, each
    /// `copy_height` rows (1 and the map's height unless [`Neighbourhoods::stacked`]): a
    /// neighbourhood lies inside one copy, and `Pos::y` counts rows from the first copy's top.
    copies: usize,
    copy_height: usize,
}

impl Neighbourhoods {
    /// `size` must fit inside the exemplar (checked by the caller's schedule).
    #[must_use]
    pub fn new(exemplar: FeatureMap, size: usize) -> Self {
        assert!(
            size >= 1 && size <= exemplar.width && size <= exemplar.height,
            "neighbourhood fits"
        );
        let weights = gaussian_falloff(size, exemplar.dims);
        Neighbourhoods {
            copy_height: exemplar.height,
            exemplar,
            size,
            weights,
            transformed: Vec::new(),
            copies: 1,
        }
    }

    /// The neighbourhoods of several maps of one size (the same exemplar moved by fractions
    /// of a pixel, for sub-pixel matches), stacked into one map so that every search and
    /// distance runs unchanged. A position's copy is `y / copy_height`
    /// ([`Neighbourhoods::copy_of`]).
    #[must_use]
    pub fn stacked(maps: &[FeatureMap], size: usize) -> Self {
        let first = &maps[0];
        assert!(
            maps.iter()
                .all(|m| (m.width, m.height, m.dims) == (first.width, first.height, first.dims)),
            "stacked maps share a size"
        );
        let data = maps.iter().flat_map(|m| m.data.iter().copied()).collect();
        let map = FeatureMap {
            width: first.width,
            height: first.height * maps.len(),
            dims: first.dims,
            data,
        };
        let mut space = Neighbourhoods::new(map, size);
        assert!(size <= first.height, "neighbourhood fits a copy");
        space.copies = maps.len();
        space.copy_height = first.height;
        space
    }

    /// Number of stacked copies (1 unless [`Neighbourhoods::stacked`]).
    #[must_use]
    pub fn copies(&self) -> usize {
        self.copies
    }

    /// The copy a position lies in and its position within that copy.
    #[must_use]
    pub fn copy_of(&self, pos: Pos) -> (usize, Pos) {
        let copy = pos.y as usize / self.copy_height;
        (
            copy,
            Pos::new(pos.x as usize, pos.y as usize - copy * self.copy_height),
        )
    }

    /// The position `local` within copy `copy`.
    #[must_use]
    pub fn in_copy(&self, copy: usize, local: Pos) -> Pos {
        Pos::new(local.x as usize, local.y as usize + copy * self.copy_height)
    }

    /// The neighbourhoods of `exemplar` stored as `transform(vector)`, compared under
    /// `weights` (`size * size * dims` long, like the vectors). `transform` maps a gathered
    /// neighbourhood (first argument) to its transformed vector of the same length (second).
    /// Memory: `count() * vector_len()` values.
    #[must_use]
    pub fn transformed(
        exemplar: FeatureMap,
        size: usize,
        weights: Vec<f32>,
        mut transform: impl FnMut(&[f32], &mut [f32]),
    ) -> Self {
        let mut space = Neighbourhoods::new(exemplar, size);
        assert_eq!(weights.len(), space.vector_len(), "one weight per value");
        debug_assert_eq!(space.copies, 1, "transformed spaces are not stacked");
        let len = space.vector_len();
        let mut vectors = vec![0.0; space.count() * len];
        let mut gathered = vec![0.0; len];
        for (i, out) in vectors.chunks_exact_mut(len).enumerate() {
            space.copy_to(space.pos_of(i), &mut gathered);
            transform(&gathered, out);
        }
        space.weights = weights;
        space.transformed = vectors;
        space
    }

    /// Whether vectors are stored transformed (see [`Neighbourhoods::transformed`]).
    #[must_use]
    pub fn is_transformed(&self) -> bool {
        !self.transformed.is_empty()
    }

    /// The vector at `pos` as rows: a slice from its first value and the stride between rows
    /// (the exemplar map's row, or `row_len` when stored transformed).
    #[inline]
    fn rows_of(&self, pos: Pos) -> (&[f32], usize) {
        let dims = self.exemplar.dims;
        if self.transformed.is_empty() {
            let width = self.exemplar.width;
            let start = (pos.y as usize * width + pos.x as usize) * dims;
            (&self.exemplar.data[start..], width * dims)
        } else {
            let nx = self.extent().0;
            let start = (pos.y as usize * nx + pos.x as usize) * self.vector_len();
            (&self.transformed[start..], self.size * dims)
        }
    }

    /// Values `dy * row_len .. (dy + 1) * row_len` of the vector at `pos`, with `row_len =
    /// size * dims` (a row of pixels, or a slice of the transformed vector).
    #[inline]
    fn part(&self, pos: Pos, dy: usize) -> &[f32] {
        if self.transformed.is_empty() {
            self.exemplar
                .row(pos.x as usize, pos.y as usize + dy, self.size)
        } else {
            let nx = self.extent().0;
            let len = self.vector_len();
            let row_len = self.size * self.exemplar.dims;
            let start = (pos.y as usize * nx + pos.x as usize) * len + dy * row_len;
            &self.transformed[start..start + row_len]
        }
    }

    #[must_use]
    pub fn size(&self) -> usize {
        self.size
    }

    #[must_use]
    pub fn dims(&self) -> usize {
        self.exemplar.dims
    }

    /// Length of one neighbourhood vector: `size * size * dims`.
    #[must_use]
    pub fn vector_len(&self) -> usize {
        self.size * self.size * self.exemplar.dims
    }

    /// Multiplies the weight of every value of feature dimension `d` by `per_dim[d]` (one
    /// factor per dimension of the exemplar's feature map): a weighted distance per channel.
    pub fn weigh_dims(&mut self, per_dim: &[f32]) {
        let dims = self.exemplar.dims;
        assert_eq!(per_dim.len(), dims, "one factor per dimension");
        for (i, w) in self.weights.iter_mut().enumerate() {
            *w *= per_dim[i % dims];
        }
    }

    /// The per-value weights (Gaussian fall-off), `vector_len()` long.
    #[must_use]
    pub fn weights(&self) -> &[f32] {
        &self.weights
    }

    #[must_use]
    pub fn exemplar(&self) -> &FeatureMap {
        &self.exemplar
    }

    /// Number of valid top-left corners along x and y (in each copy).
    #[must_use]
    pub fn extent(&self) -> (usize, usize) {
        (
            self.exemplar.width - self.size + 1,
            self.copy_height - self.size + 1,
        )
    }

    #[must_use]
    pub fn count(&self) -> usize {
        let (nx, ny) = self.extent();
        nx * ny * self.copies
    }

    /// The `i`-th neighbourhood in scan order (copy after copy).
    #[must_use]
    pub fn pos_of(&self, i: usize) -> Pos {
        let (nx, ny) = self.extent();
        let (copy, r) = (i / (nx * ny), i % (nx * ny));
        Pos::new(r % nx, r / nx + copy * self.copy_height)
    }

    /// Clamps a corner into the valid range (used after propagation and random jumps): into
    /// the copy whose rows `y` falls in.
    #[must_use]
    pub fn clamp(&self, x: i64, y: i64) -> Pos {
        let rows = (self.copies * self.copy_height) as i64;
        let copy = (y.clamp(0, rows - 1) / self.copy_height as i64) as usize;
        self.clamp_from(
            self.in_copy(copy, Pos::default()),
            x,
            y - (copy * self.copy_height) as i64,
        )
    }

    /// `base` moved by (dx, dy) and clamped into `base`'s own copy.
    #[must_use]
    pub fn clamp_from(&self, base: Pos, dx: i64, dy: i64) -> Pos {
        let (nx, ny) = self.extent();
        let (copy, local) = self.copy_of(base);
        self.in_copy(
            copy,
            Pos::new(
                (i64::from(local.x) + dx).clamp(0, nx as i64 - 1) as usize,
                (i64::from(local.y) + dy).clamp(0, ny as i64 - 1) as usize,
            ),
        )
    }

    /// Weighted squared distance between a query vector (laid out row by row like a
    /// neighbourhood) and the neighbourhood at `pos`. Stops early, returning a value above `bound`,
    /// as soon as the partial sum exceeds `bound`.
    #[inline]
    #[must_use]
    pub fn distance(&self, query: &[f32], pos: Pos, bound: f32) -> f32 {
        self.distance_with(query, &self.weights, pos, bound)
    }

    /// [`Neighbourhoods::distance`] with per-value `weights` of the query's own (soft
    /// constraints weigh constrained pixels more, Kwatra et al. 2005 section 4).
    ///
    /// Most candidates are rejected after two or three rows, so the rows of the usual lengths
    /// (8, 16 and 32 RGB or grey pixels) get loops of a fixed length, unrolled and without
    /// bounds checks; the sums are the same, added in the same order. Grey rows get them too:
    /// with the loop of any length, a grey exemplar runs texture optimisation at about half the
    /// speed of an RGB one.
    #[inline]
    #[must_use]
    pub fn distance_with(&self, query: &[f32], weights: &[f32], pos: Pos, bound: f32) -> f32 {
        let query = InPlace {
            values: query,
            gains: None,
            stride: self.size * self.exemplar.dims,
        };
        self.distance_in_place(query, weights, pos, bound)
    }

    /// [`Neighbourhoods::distance_with`] for a query read in place (see [`InPlace`]).
    #[inline]
    #[must_use]
    pub fn distance_in_place(
        &self,
        query: InPlace<'_>,
        weights: &[f32],
        pos: Pos,
        bound: f32,
    ) -> f32 {
        match self.size * self.exemplar.dims {
            8 => self.rows_distance::<8>(query, weights, pos, bound),
            16 => self.rows_distance::<16>(query, weights, pos, bound),
            24 => self.rows_distance::<24>(query, weights, pos, bound),
            32 => self.rows_distance::<32>(query, weights, pos, bound),
            48 => self.rows_distance::<48>(query, weights, pos, bound),
            96 => self.rows_distance::<96>(query, weights, pos, bound),
            _ => self.rows_distance::<0>(query, weights, pos, bound),
        }
    }

    /// [`Neighbourhoods::distance_in_place`] over rows of `N` values (0: of any length).
    #[inline(always)]
    fn rows_distance<const N: usize>(
        &self,
        query: InPlace<'_>,
        weights: &[f32],
        pos: Pos,
        bound: f32,
    ) -> f32 {
        let row_len = self.size * self.exemplar.dims;
        let stride = query.stride;
        // The neighbourhood's rows as one slice and a stride, decided once rather than per row.
        let (ex, ex_stride) = self.rows_of(pos);
        let mut sum = 0.0;
        // Rows centre-out (half, half - 1, half + 1, ...): the fall-off weighs the centre rows
        // most, so a poor candidate passes the bound in fewer rows (most are rejected within
        // two or three).
        let half = self.size / 2;
        for i in 0..self.size {
            let dy = if i % 2 == 0 {
                half + i / 2
            } else {
                half - 1 - i / 2
            };
            let row = &ex[dy * ex_stride..dy * ex_stride + row_len];
            let q = &query.values[dy * stride..dy * stride + row_len];
            let g = &weights[dy * row_len..(dy + 1) * row_len];
            let gains = query.gains.map(|v| &v[dy * stride..dy * stride + row_len]);
            sum += match (N, gains) {
                (0, None) => weighted_ssd(q, row, g),
                (0, Some(gains)) => gained_weighted_ssd(q, row, g, gains),
                _ => fixed_weighted_ssd::<N>(q, row, g, gains),
            };
            if sum > bound {
                return sum;
            }
        }
        sum
    }

    /// Copies the neighbourhood's vector at `pos` (transformed, when stored so) into `out`
    /// (`vector_len()` values).
    pub fn copy_to(&self, pos: Pos, out: &mut [f32]) {
        let row_len = self.size * self.exemplar.dims;
        for dy in 0..self.size {
            let row = self.part(pos, dy);
            out[dy * row_len..(dy + 1) * row_len].copy_from_slice(row);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    pub(crate) fn ramp_map(width: usize, height: usize, dims: usize) -> FeatureMap {
        let data = (0..width * height * dims)
            .map(|i| ((i * 7919) % 101) as f32 / 101.0)
            .collect();
        FeatureMap {
            width,
            height,
            dims,
            data,
        }
    }

    #[test]
    fn falloff_peaks_at_the_centre_and_is_symmetric() {
        let g = gaussian_falloff(4, 2);
        assert_eq!(g.len(), 32);
        assert_eq!(g[0], g[1]); // both dims of a pixel share the weight
        assert_eq!(g[(4 + 1) * 2], g[(2 * 4 + 2) * 2]);
        assert!(g[(4 + 1) * 2] > g[0]);
    }

    #[test]
    fn weighted_ssd_matches_the_plain_loop_for_every_length() {
        for len in [1, 7, 8, 9, 33] {
            let a: Vec<f32> = (0..len).map(|i| i as f32 * 0.3).collect();
            let b: Vec<f32> = (0..len).map(|i| (len - i) as f32 * 0.2).collect();
            let g: Vec<f32> = (0..len).map(|i| 1.0 / (1.0 + i as f32)).collect();
            let plain: f32 = (0..len).map(|i| g[i] * (a[i] - b[i]).powi(2)).sum();
            assert!((weighted_ssd(&a, &b, &g) - plain).abs() < 1e-4 * plain.max(1.0));
        }
    }

    #[test]
    fn fixed_length_rows_give_the_sums_of_rows_of_any_length_to_the_bit() {
        // Grey (1), two-value and RGB (3) rows of 8, 16 and 32 pixels: every row length the
        // distance has a fixed-length loop for, and some it has not, against the loop of any
        // length and against a direct weighted SSD.
        for dims in [1, 2, 3] {
            for size in [8, 16, 32] {
                let n = Neighbourhoods::new(ramp_map(size + 9, size + 5, dims), size);
                let mut q = vec![0.0; n.vector_len()];
                n.copy_to(Pos::new(4, 3), &mut q);
                for v in q.iter_mut().step_by(5) {
                    *v = 1.0 - *v;
                }
                let in_place = InPlace {
                    values: &q,
                    gains: None,
                    stride: size * dims,
                };
                for pos in [Pos::new(0, 0), Pos::new(9, 5), Pos::new(2, 4)] {
                    let any = n.rows_distance::<0>(in_place, &n.weights, pos, f32::INFINITY);
                    let fixed = n.distance(&q, pos, f32::INFINITY);
                    assert_eq!(fixed.to_bits(), any.to_bits(), "dims {dims}, size {size}");
                    let mut row = vec![0.0; n.vector_len()];
                    n.copy_to(pos, &mut row);
                    let direct: f32 = (0..row.len())
                        .map(|i| n.weights[i] * (q[i] - row[i]).powi(2))
                        .sum();
                    assert!(
                        (fixed - direct).abs() <= 1e-4 * direct,
                        "{fixed} vs {direct}"
                    );
                    let bounded = n.distance(&q, pos, direct * 0.2);
                    assert!(bounded > direct * 0.2 && bounded <= fixed);
                }
            }
        }
    }

    #[test]
    fn distance_to_a_copy_is_zero_and_early_exit_exceeds_the_bound() {
        let n = Neighbourhoods::new(ramp_map(10, 9, 3), 4);
        assert_eq!(n.extent(), (7, 6));
        assert_eq!(n.count(), 42);
        let mut q = vec![0.0; n.vector_len()];
        n.copy_to(Pos::new(3, 2), &mut q);
        assert_eq!(n.distance(&q, Pos::new(3, 2), f32::INFINITY), 0.0);
        let full = n.distance(&q, Pos::new(0, 0), f32::INFINITY);
        assert!(full > 0.0);
        assert!(n.distance(&q, Pos::new(0, 0), full * 0.1) > full * 0.1);
        assert_eq!(n.clamp(-5, 99), Pos::new(0, 5));
        assert_eq!(n.pos_of(8), Pos::new(1, 1));
    }

    #[test]
    fn stacked_copies_keep_every_neighbourhood_inside_one_copy() {
        let (a, b) = (ramp_map(10, 9, 3), ramp_map(10, 9, 3));
        let b = FeatureMap {
            data: b.data.iter().map(|v| 1.0 - v).collect(),
            ..b
        };
        let n = Neighbourhoods::stacked(&[a, b.clone()], 4);
        assert_eq!((n.copies(), n.extent(), n.count()), (2, (7, 6), 84));
        // Scan order runs through copy 0, then copy 1 (rows 9 to 17).
        assert_eq!(n.pos_of(41), Pos::new(6, 5));
        assert_eq!(n.pos_of(42), Pos::new(0, 9));
        assert_eq!(n.copy_of(Pos::new(3, 11)), (1, Pos::new(3, 2)));
        // Clamping never leaves a copy, nor straddles two.
        assert_eq!(n.clamp_from(Pos::new(3, 11), 9, 9), Pos::new(6, 14));
        assert_eq!(n.clamp_from(Pos::new(3, 11), -9, -9), Pos::new(0, 9));
        assert_eq!(n.clamp(2, 7), Pos::new(2, 5));
        assert_eq!(n.clamp(2, 13), Pos::new(2, 13));
        assert_eq!(n.clamp(2, 40), Pos::new(2, 14));
        // A neighbourhood of copy 1 is read from copy 1.
        let alone = Neighbourhoods::new(b, 4);
        let mut q = vec![0.0; n.vector_len()];
        alone.copy_to(Pos::new(3, 2), &mut q);
        assert_eq!(
            n.distance(&q, n.in_copy(1, Pos::new(3, 2)), f32::INFINITY),
            0.0
        );
        assert!(n.distance(&q, Pos::new(3, 2), f32::INFINITY) > 0.0);
    }

    #[test]
    fn transformed_neighbourhoods_store_the_map_of_each_vector() {
        // A reversal with doubled values: distance between transformed vectors under unit
        // weights is 4x the plain unweighted distance.
        let map = ramp_map(9, 8, 2);
        let plain = Neighbourhoods::new(map.clone(), 3);
        let len = plain.vector_len();
        let t = Neighbourhoods::transformed(map, 3, vec![1.0; len], |v, out| {
            for (o, x) in out.iter_mut().zip(v.iter().rev()) {
                *o = 2.0 * x;
            }
        });
        assert!(t.is_transformed() && !plain.is_transformed());
        let mut q = vec![0.0; len];
        let mut tq = vec![0.0; len];
        plain.copy_to(Pos::new(2, 1), &mut q);
        t.copy_to(Pos::new(2, 1), &mut tq);
        let reversed: Vec<f32> = q.iter().rev().map(|x| 2.0 * x).collect();
        assert_eq!(tq, reversed);
        for pos in [Pos::new(0, 0), Pos::new(6, 5), Pos::new(3, 2)] {
            let unweighted = plain.distance_with(&q, &vec![1.0; len], pos, f32::INFINITY);
            let d = t.distance(&tq, pos, f32::INFINITY);
            assert!((d - 4.0 * unweighted).abs() < 1e-4, "{d} vs {unweighted}");
        }
    }
}
