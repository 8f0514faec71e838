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
    let mut acc = [0.0f32; 8];
    let chunks = a.len() / 8 * 8;
    for ((ca, cb), cg) in a[..chunks]
        .chunks_exact(8)
        .zip(b[..chunks].chunks_exact(8))
        .zip(g[..chunks].chunks_exact(8))
    {
        for k in 0..8 {
            let d = ca[k] - cb[k];
            acc[k] += cg[k] * d * d;
        }
    }
    let mut sum = (acc[0] + acc[4]) + (acc[1] + acc[5]) + ((acc[2] + acc[6]) + (acc[3] + acc[7]));
    for k in chunks..a.len() {
        let d = a[k] - b[k];
        sum += g[k] * d * d;
    }
    sum
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
            exemplar,
            size,
            weights,
            transformed: Vec::new(),
        }
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

    /// The per-value weights (Gaussian fall-off), `vector_len()` long.
    #[must_use]
    pub fn weights(&self) -> &[f32] {
        &self.weights
    }

    #[must_use]
    pub fn exemplar(&self) -> &FeatureMap {
        &self.exemplar
    }

    /// Number of valid top-left corners along x and y.
    #[must_use]
    pub fn extent(&self) -> (usize, usize) {
        (
            self.exemplar.width - self.size + 1,
            self.exemplar.height - self.size + 1,
        )
    }

    #[must_use]
    pub fn count(&self) -> usize {
        let (nx, ny) = self.extent();
        nx * ny
    }

    /// The `i`-th neighbourhood in scan order.
    #[must_use]
    pub fn pos_of(&self, i: usize) -> Pos {
        let nx = self.extent().0;
        Pos::new(i % nx, i / nx)
    }

    /// Clamps a corner into the valid range (used after propagation and random jumps).
    #[must_use]
    pub fn clamp(&self, x: i64, y: i64) -> Pos {
        let (nx, ny) = self.extent();
        Pos::new(
            x.clamp(0, nx as i64 - 1) as usize,
            y.clamp(0, ny as i64 - 1) as usize,
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
    #[inline]
    #[must_use]
    pub fn distance_with(&self, query: &[f32], weights: &[f32], pos: Pos, bound: f32) -> f32 {
        let row_len = self.size * self.exemplar.dims;
        let mut sum = 0.0;
        for dy in 0..self.size {
            let row = self.part(pos, dy);
            let range = dy * row_len..(dy + 1) * row_len;
            sum += weighted_ssd(&query[range.clone()], row, &weights[range]);
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
