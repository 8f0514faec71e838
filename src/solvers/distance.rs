//! Exact Euclidean distance transform with nearest-pixel pointers (Felzenszwalb & Huttenlocher
//! 2012: the lower envelope of parabolas, one pass per axis). Wu & Yu 2004 compute theirs by level
//! sets; any exact transform serves, and this one is linear in the pixels. No well-kept crate
//! offers the pointers for wasm32, so it is written here and checked against brute force.

/// The squared distance to the nearest seed of every pixel and that seed's index (`y * w + x`),
/// [`DistanceMap::NONE`] where there is no seed at all. Pointers are `u32` (grids up to 4
/// billion pixels): a 12-megapixel photo's four feature buckets hold 48 million of them.
pub struct DistanceMap {
    pub width: usize,
    pub height: usize,
    pub squared: Vec<f32>,
    pub nearest: Vec<u32>,
}

impl DistanceMap {
    /// The pointer of a pixel with no seed anywhere.
    pub const NONE: u32 = u32::MAX;

    /// The transform of the `width` x `height` grid whose seeds are `true` (fewer than
    /// `u32::MAX` pixels).
    #[must_use]
    pub fn new(width: usize, height: usize, seeds: &[bool]) -> DistanceMap {
        let n = width * height;
        debug_assert_eq!(seeds.len(), n);
        debug_assert!(n < u32::MAX as usize);
        let far = f32::INFINITY;
        // Columns first: for every pixel, the nearest seed in its column.
        let mut col_d = vec![far; n];
        let mut col_y = vec![Self::NONE; n];
        let mut f = vec![0.0f32; width.max(height)];
        let mut d = vec![0.0f32; width.max(height)];
        let mut arg = vec![0usize; width.max(height)];
        let mut scratch = Envelope::new(width.max(height));
        for x in 0..width {
            for y in 0..height {
                f[y] = if seeds[y * width + x] { 0.0 } else { far };
            }
            scratch.transform(&f[..height], &mut d[..height], &mut arg[..height]);
            for y in 0..height {
                col_d[y * width + x] = d[y];
                col_y[y * width + x] = if d[y].is_finite() {
                    arg[y] as u32
                } else {
                    Self::NONE
                };
            }
        }
        // Then rows, over the column distances.
        let mut squared = vec![far; n];
        let mut nearest = vec![Self::NONE; n];
        for y in 0..height {
            f[..width].copy_from_slice(&col_d[y * width..(y + 1) * width]);
            scratch.transform(&f[..width], &mut d[..width], &mut arg[..width]);
            for x in 0..width {
                let i = y * width + x;
                squared[i] = d[x];
                if d[x].is_finite() {
                    let sx = arg[x];
                    nearest[i] = col_y[y * width + sx] * width as u32 + sx as u32;
                }
            }
        }
        DistanceMap {
            width,
            height,
            squared,
            nearest,
        }
    }
}

/// The 1-D transform's working space: d(q) = min_p ((q - p)^2 + f(p)).
struct Envelope {
    v: Vec<usize>,
    z: Vec<f32>,
}

impl Envelope {
    fn new(len: usize) -> Envelope {
        Envelope {
            v: vec![0; len],
            z: vec![0.0; len + 1],
        }
    }

    fn transform(&mut self, f: &[f32], d: &mut [f32], arg: &mut [usize]) {
        let n = f.len();
        // Only finite samples take part; with none, everything is infinite.
        let mut k: isize = -1;
        for q in 0..n {
            if !f[q].is_finite() {
                continue;
            }
            loop {
                if k < 0 {
                    k = 0;
                    self.v[0] = q;
                    self.z[0] = f32::NEG_INFINITY;
                    self.z[1] = f32::INFINITY;
                    break;
                }
                let p = self.v[k as usize];
                let s =
                    ((f[q] + (q * q) as f32) - (f[p] + (p * p) as f32)) / (2.0 * (q - p) as f32);
                if s <= self.z[k as usize] {
                    k -= 1;
                    continue;
                }
                k += 1;
                self.v[k as usize] = q;
                self.z[k as usize] = s;
                self.z[k as usize + 1] = f32::INFINITY;
                break;
            }
        }
        if k < 0 {
            d.fill(f32::INFINITY);
            arg.fill(usize::MAX);
            return;
        }
        let mut j = 0usize;
        for q in 0..n {
            while self.z[j + 1] < q as f32 {
                j += 1;
            }
            let p = self.v[j];
            let dq = q as f32 - p as f32;
            d[q] = dq * dq + f[p];
            arg[q] = p;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Rng;

    #[test]
    fn distances_and_pointers_equal_brute_force() {
        for seed in 0..20u64 {
            let mut rng = Rng::new(seed);
            let (w, h) = (3 + rng.index(30), 3 + rng.index(25));
            let density = [0.002, 0.02, 0.2][seed as usize % 3];
            let seeds: Vec<bool> = (0..w * h).map(|_| rng.next_f32() < density).collect();
            let map = DistanceMap::new(w, h, &seeds);
            let points: Vec<usize> = (0..w * h).filter(|&i| seeds[i]).collect();
            for i in 0..w * h {
                let (x, y) = ((i % w) as f32, (i / w) as f32);
                let d2 = |j: usize| {
                    let (sx, sy) = ((j % w) as f32, (j / w) as f32);
                    (x - sx) * (x - sx) + (y - sy) * (y - sy)
                };
                let best = points.iter().map(|&j| d2(j)).fold(f32::INFINITY, f32::min);
                assert_eq!(map.squared[i], best, "seed {seed} pixel {i}");
                if points.is_empty() {
                    assert_eq!(map.nearest[i], DistanceMap::NONE);
                } else {
                    let j = map.nearest[i] as usize;
                    assert!(seeds[j], "points at a seed");
                    assert_eq!(d2(j), best, "seed {seed} pixel {i}: pointer");
                }
            }
        }
    }
}
