//! The SSD search of section 5 (eq. 6) over (x, y, t) volumes, for the spatio-temporal sub-patch
//! matching of video (section 7.C): the same sums of cross-correlations as the image search in
//! `mod.rs`, with a 3-D transform ([`Transform::new_volume`]). An image is the depth-1 case.
//!
//! Unlike the image search it keeps no spectra of the patch between calls: a volume's spectra
//! are large (tens of MB), and a video synthesis searches a small output sub-volume (the error
//! region) against the input, so recomputing the patch side is cheap next to holding it. Three
//! spectra and one real field are alive at any time.

use super::transform::Transform;
use super::{MIN_AREA, range_length};
use crate::core::{Error, Result};
use crate::solvers::fft::{Complex, smooth_size};

/// The largest 3-D transform, in values. Three spectra of half that (complex, `f64`) and one real
/// field: 4 Mi values take 128 MiB, the most a search may add to a video's working set.
pub const MAX_VOLUME_TRANSFORM_VALUES: usize = 1 << 22;

/// Bytes a 3-D search of transform size `values` allocates: three half spectra of 16-byte complex
/// values and one real field of 8-byte values.
#[must_use]
pub fn volume_search_bytes(values: usize) -> usize {
    values * 8 + 3 * (values / 2 + values / 64 + 1) * 16
}

/// A volume to search over or with: frames of interleaved channels, `data[((t * height + y) *
/// width + x) * channels + c]`, with an optional weight per voxel (`None`: all 1).
#[derive(Debug, Clone, Copy)]
pub struct VolumeView<'a> {
    pub data: &'a [f32],
    pub width: usize,
    pub height: usize,
    pub depth: usize,
    pub channels: usize,
    pub weights: Option<&'a [f32]>,
}

impl VolumeView<'_> {
    fn voxels(&self) -> usize {
        self.width * self.height * self.depth
    }

    fn check(&self, name: &'static str) -> Result<()> {
        let voxels = self.voxels();
        if voxels == 0 || self.channels == 0 {
            return Err(Error::InvalidParameter {
                name,
                reason: format!(
                    "is empty: {}x{}x{} with {} channels",
                    self.width, self.height, self.depth, self.channels
                ),
            });
        }
        if self.data.len() != voxels * self.channels {
            return Err(Error::LengthMismatch {
                what: name,
                expected: voxels * self.channels,
                actual: self.data.len(),
            });
        }
        if let Some(w) = self.weights {
            if w.len() != voxels {
                return Err(Error::LengthMismatch {
                    what: name,
                    expected: voxels,
                    actual: w.len(),
                });
            }
            if let Some(i) = w.iter().position(|v| !v.is_finite() || *v < 0.0) {
                return Err(Error::InvalidParameter {
                    name,
                    reason: format!("weight {} at voxel {i} is not finite and >= 0", w[i]),
                });
            }
        }
        if let Some(i) = self.data.iter().position(|v| !v.is_finite()) {
            return Err(Error::InvalidParameter {
                name,
                reason: format!("value {i} is not finite"),
            });
        }
        Ok(())
    }

    fn weight(&self, voxel: usize) -> f64 {
        f64::from(self.weights.map_or(1.0, |w| w[voxel]))
    }

    /// Fills the transform's real field with `value(voxel colour, weight)`, zero elsewhere.
    fn scatter(
        &self,
        field: &mut [f64],
        (nx, ny): (usize, usize),
        value: impl Fn(&[f32], f64) -> f64,
    ) {
        field.fill(0.0);
        let (w, h, c) = (self.width, self.height, self.channels);
        for (v, colour) in self.data.chunks_exact(c).enumerate() {
            let weight = self.weight(v);
            if weight > 0.0 {
                let (x, y, t) = (v % w, v / w % h, v / (w * h));
                field[(t * ny + y) * nx + x] += value(colour, weight);
            }
        }
    }
}

/// `C(t)` and `A(t)` (see the module docs of `fft_ssd`) for every translation `t = (tx, ty, tt)`
/// at which the patch overlaps the output by at least one voxel.
#[derive(Debug, Clone, PartialEq)]
pub struct VolumeSsdMap {
    /// Number of translations along x, y and t.
    pub size: (usize, usize, usize),
    /// The translation at index 0: `(1 - patch width, 1 - patch height, 1 - patch depth)`.
    pub first_offset: (isize, isize, isize),
    pub costs: Vec<f32>,
    pub areas: Vec<f32>,
}

impl VolumeSsdMap {
    /// `(C(t), A(t))` at translation `(tx, ty, tt)`, `None` outside the map.
    #[must_use]
    pub fn get(&self, tx: isize, ty: isize, tt: isize) -> Option<(f32, f32)> {
        let i = usize::try_from(tx - self.first_offset.0).ok()?;
        let j = usize::try_from(ty - self.first_offset.1).ok()?;
        let k = usize::try_from(tt - self.first_offset.2).ok()?;
        let (w, h, d) = self.size;
        (i < w && j < h && k < d).then(|| {
            let index = (k * h + j) * w + i;
            (self.costs[index], self.areas[index])
        })
    }
}

/// The transform size for an output and a patch: at least `output + patch - 1` along each axis
/// so that the circular correlation does not wrap, an even width for the half-length rows.
#[must_use]
pub fn volume_transform_size(
    output: (usize, usize, usize),
    patch: (usize, usize, usize),
) -> (usize, usize, usize) {
    (
        2 * smooth_size((output.0 + patch.0 - 1).div_ceil(2)),
        smooth_size(output.1 + patch.1 - 1),
        smooth_size(output.2 + patch.2 - 1),
    )
}

/// The translations a [`volume_ssd_map_range`] computes: `count` of them from `first`, along x,
/// y and t.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct VolumeRange {
    pub first: (isize, isize, isize),
    pub count: (usize, usize, usize),
}

/// The transform size of a [`volume_ssd_map_range`]: along each axis only as long as the offsets
/// and the patch span together (see [`super::SsdSearch::search_range`] for the image case).
#[must_use]
pub fn volume_range_transform_size(
    output: (usize, usize, usize),
    patch: (usize, usize, usize),
    range: VolumeRange,
) -> (usize, usize, usize) {
    let (f, c) = (range.first, range.count);
    (
        2 * smooth_size(range_length(output.0, f.0, c.0, patch.0).div_ceil(2)),
        smooth_size(range_length(output.1, f.1, c.1, patch.1)),
        smooth_size(range_length(output.2, f.2, c.2, patch.2)),
    )
}

/// The cost and overlap of every translation of `patch` over `output` (an open boundary: voxels
/// past the output's border count for nothing). Fails on empty or inconsistent volumes, weights
/// that are negative or not finite, values that are not finite, different channel counts, or a
/// transform of more than [`MAX_VOLUME_TRANSFORM_VALUES`].
pub fn volume_ssd_map(output: VolumeView<'_>, patch: VolumeView<'_>) -> Result<VolumeSsdMap> {
    check_pair(output, patch)?;
    let size = (
        output.width + patch.width - 1,
        output.height + patch.height - 1,
        output.depth + patch.depth - 1,
    );
    let first = (
        1 - patch.width as isize,
        1 - patch.height as isize,
        1 - patch.depth as isize,
    );
    let n = volume_transform_size(
        (output.width, output.height, output.depth),
        (patch.width, patch.height, patch.depth),
    );
    correlate(output, patch, n, VolumeRange { first, count: size })
}

/// Like [`volume_ssd_map`], for the translations of `range` only (inside the output or not), with
/// a transform only as large as they need: an entire-patch placement reads the output over the
/// union of its candidates' footprints, and its offsets all lie in that window. Fails as
/// [`volume_ssd_map`] does, and on an empty range.
pub fn volume_ssd_map_range(
    output: VolumeView<'_>,
    patch: VolumeView<'_>,
    range: VolumeRange,
) -> Result<VolumeSsdMap> {
    check_pair(output, patch)?;
    let (cx, cy, ct) = range.count;
    if cx == 0 || cy == 0 || ct == 0 {
        return Err(Error::InvalidParameter {
            name: "offset range",
            reason: format!("is empty ({cx}x{cy}x{ct} offsets)"),
        });
    }
    let n = volume_range_transform_size(
        (output.width, output.height, output.depth),
        (patch.width, patch.height, patch.depth),
        range,
    );
    correlate(output, patch, n, range)
}

/// Fails on either volume's defects or different channel counts.
fn check_pair(output: VolumeView<'_>, patch: VolumeView<'_>) -> Result<()> {
    output.check("output volume")?;
    patch.check("patch volume")?;
    if output.channels != patch.channels {
        return Err(Error::InvalidParameter {
            name: "patch volume",
            reason: format!(
                "has {} channels but the output has {}",
                patch.channels, output.channels
            ),
        });
    }
    Ok(())
}

/// The search proper (the volumes checked) over an `nx` x `ny` x `nz` transform, read out at the offsets of `range`.
fn correlate(
    output: VolumeView<'_>,
    patch: VolumeView<'_>,
    (nx, ny, nz): (usize, usize, usize),
    range: VolumeRange,
) -> Result<VolumeSsdMap> {
    let values = nx * ny * nz;
    if values > MAX_VOLUME_TRANSFORM_VALUES {
        return Err(Error::InvalidParameter {
            name: "3-D FFT search",
            reason: format!(
                "a {nx}x{ny}x{nz} transform ({values} values) is more than the \
                 {MAX_VOLUME_TRANSFORM_VALUES} supported; use a smaller search region or input"
            ),
        });
    }
    let mut transform = Transform::new_volume(nx, ny, nz);
    let spectrum_len = (nx / 2 + 1) * ny * nz;
    let mut field = vec![0.0f64; values];
    let mut a = vec![Complex::<f64>::default(); spectrum_len];
    let mut b = vec![Complex::<f64>::default(); spectrum_len];
    let mut acc = vec![Complex::<f64>::default(); spectrum_len];
    let n = (nx, ny);

    // A(t) = corr(w_O, w_I).
    output.scatter(&mut field, n, |_, w| w);
    transform.forward(&field, &mut a);
    patch.scatter(&mut field, n, |_, w| w);
    transform.forward(&field, &mut b);
    multiply_conj(&mut acc, &a, &b, 1.0, false);
    transform.inverse(&mut acc, &mut field);
    let (size, first) = (range.count, range.first);
    let mut areas = read_map(&field, (nx, ny, nz), size, first);

    // C(t) = corr(w_O O^2, w_I) + corr(w_O, w_I I^2) - 2 sum_c corr(w_O O_c, w_I I_c); `b` still
    // holds F(w_I) and `a` F(w_O).
    output.scatter(&mut field, n, |colour, w| w * squared_norm(colour));
    transform.forward(&field, &mut acc);
    for (o, &y) in acc.iter_mut().zip(&b) {
        *o *= y.conj();
    }
    patch.scatter(&mut field, n, |colour, w| w * squared_norm(colour));
    transform.forward(&field, &mut b);
    multiply_conj(&mut acc, &a, &b, 1.0, true);
    for channel in 0..output.channels {
        output.scatter(&mut field, n, |colour, w| w * f64::from(colour[channel]));
        transform.forward(&field, &mut a);
        patch.scatter(&mut field, n, |colour, w| w * f64::from(colour[channel]));
        transform.forward(&field, &mut b);
        multiply_conj(&mut acc, &a, &b, -2.0, true);
    }
    transform.inverse(&mut acc, &mut field);
    let mut costs = read_map(&field, (nx, ny, nz), size, first);
    for (cost, area) in costs.iter_mut().zip(areas.iter_mut()) {
        if *area < MIN_AREA {
            *area = 0.0;
            *cost = 0.0;
        }
        *cost = cost.max(0.0);
    }
    Ok(VolumeSsdMap {
        size,
        first_offset: first,
        costs,
        areas,
    })
}

/// `out = (out if accumulate) + factor * a * conj(b)`.
fn multiply_conj(
    out: &mut [Complex<f64>],
    a: &[Complex<f64>],
    b: &[Complex<f64>],
    factor: f64,
    accumulate: bool,
) {
    crate::solvers::fft::correlate_spectra(out, a, b, factor, accumulate);
}

/// Reads translation `t` from `t mod n` of the correlation and undoes the transform's scale.
fn read_map(
    field: &[f64],
    (nx, ny, nz): (usize, usize, usize),
    (w, h, d): (usize, usize, usize),
    first: (isize, isize, isize),
) -> Vec<f32> {
    let scale = 1.0 / (nx * ny * nz) as f64;
    let mut map = Vec::with_capacity(w * h * d);
    for k in 0..d {
        let z = (first.2 + k as isize).rem_euclid(nz as isize) as usize;
        for j in 0..h {
            let y = (first.1 + j as isize).rem_euclid(ny as isize) as usize;
            for i in 0..w {
                let x = (first.0 + i as isize).rem_euclid(nx as isize) as usize;
                map.push((field[(z * ny + y) * nx + x] * scale) as f32);
            }
        }
    }
    map
}

fn squared_norm(colour: &[f32]) -> f64 {
    colour.iter().map(|&v| f64::from(v) * f64::from(v)).sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Rng;

    fn random(rng: &mut Rng, len: usize) -> Vec<f32> {
        (0..len).map(|_| rng.next_f32()).collect()
    }

    /// The obvious SSD over every translation and every patch voxel.
    fn direct(
        output: VolumeView<'_>,
        patch: VolumeView<'_>,
        t: (isize, isize, isize),
    ) -> (f64, f64) {
        let (mut cost, mut area) = (0.0, 0.0);
        let c = output.channels;
        for pt in 0..patch.depth {
            for py in 0..patch.height {
                for px in 0..patch.width {
                    let (x, y, z) = (px as isize + t.0, py as isize + t.1, pt as isize + t.2);
                    if x < 0 || y < 0 || z < 0 {
                        continue;
                    }
                    let (x, y, z) = (x as usize, y as usize, z as usize);
                    if x >= output.width || y >= output.height || z >= output.depth {
                        continue;
                    }
                    let o = (z * output.height + y) * output.width + x;
                    let p = (pt * patch.height + py) * patch.width + px;
                    let w = output.weight(o) * patch.weight(p);
                    if w == 0.0 {
                        continue;
                    }
                    area += w;
                    for ch in 0..c {
                        let d =
                            f64::from(output.data[o * c + ch]) - f64::from(patch.data[p * c + ch]);
                        cost += w * d * d;
                    }
                }
            }
        }
        (cost, area)
    }

    /// A view of `data`, `size` = (width, height, depth), three channels.
    fn view<'a>(
        data: &'a [f32],
        (width, height, depth): (usize, usize, usize),
        weights: Option<&'a [f32]>,
    ) -> VolumeView<'a> {
        VolumeView {
            data,
            width,
            height,
            depth,
            channels: 3,
            weights,
        }
    }

    /// `map` at translation `t` equals the direct SSD and overlap there.
    fn check_against_direct(
        map: &VolumeSsdMap,
        (output, patch): (VolumeView<'_>, VolumeView<'_>),
        t: (isize, isize, isize),
    ) {
        let (cost, area) = map.get(t.0, t.1, t.2).unwrap();
        let (dc, da) = direct(output, patch, t);
        assert!((f64::from(area) - da).abs() < 1e-4, "area at {t:?}");
        assert!(
            (f64::from(cost) - dc).abs() < 1e-3 * (1.0 + dc),
            "cost at {t:?}: {cost} vs {dc}"
        );
    }

    #[test]
    fn the_3d_fft_search_equals_the_direct_ssd() {
        let mut rng = Rng::new(3);
        let (ow, oh, od, pw, ph, pd, c) = (7, 5, 6, 4, 3, 5, 3);
        let out = random(&mut rng, ow * oh * od * c);
        let pat = random(&mut rng, pw * ph * pd * c);
        let weights: Vec<f32> = (0..ow * oh * od)
            .map(|i| {
                if i % 3 == 0 {
                    0.0
                } else {
                    0.5 + (i % 5) as f32 * 0.1
                }
            })
            .collect();
        let output = view(&out, (ow, oh, od), Some(&weights));
        let patch = view(&pat, (pw, ph, pd), None);
        let map = volume_ssd_map(output, patch).unwrap();
        assert_eq!(map.size, (ow + pw - 1, oh + ph - 1, od + pd - 1));
        let mut checked = 0;
        for tt in 1 - pd as isize..od as isize {
            for ty in 1 - ph as isize..oh as isize {
                for tx in 1 - pw as isize..ow as isize {
                    check_against_direct(&map, (output, patch), (tx, ty, tt));
                    checked += 1;
                }
            }
        }
        assert_eq!(checked, map.costs.len());
        assert!(map.get(ow as isize, 0, 0).is_none());
    }

    #[test]
    fn a_range_search_equals_the_direct_ssd_at_its_offsets() {
        let mut rng = Rng::new(7);
        let (ow, oh, od, pw, ph, pd, c) = (9, 7, 6, 5, 4, 3, 3);
        let out = random(&mut rng, ow * oh * od * c);
        let pat = random(&mut rng, pw * ph * pd * c);
        let weights: Vec<f32> = (0..ow * oh * od)
            .map(|i| if i % 4 == 1 { 0.0 } else { 1.0 })
            .collect();
        let output = view(&out, (ow, oh, od), Some(&weights));
        let patch = view(&pat, (pw, ph, pd), None);
        // Offsets inside the output, partly past its far side, and partly before it.
        for range in [
            VolumeRange {
                first: (0, 0, 0),
                count: (ow - pw + 1, oh - ph + 1, od - pd + 1),
            },
            VolumeRange {
                first: (-2, 1, -1),
                count: (8, 5, 4),
            },
        ] {
            let full = volume_transform_size((ow, oh, od), (pw, ph, pd));
            let n = volume_range_transform_size((ow, oh, od), (pw, ph, pd), range);
            let map = volume_ssd_map_range(output, patch, range).unwrap();
            assert_eq!(map.size, range.count);
            for k in 0..range.count.2 as isize {
                for j in 0..range.count.1 as isize {
                    for i in 0..range.count.0 as isize {
                        let t = (range.first.0 + i, range.first.1 + j, range.first.2 + k);
                        check_against_direct(&map, (output, patch), t);
                    }
                }
            }
            assert!(n.0 * n.1 * n.2 < full.0 * full.1 * full.2, "{n:?} vs {full:?}");
        }
        let empty = VolumeRange {
            first: (0, 0, 0),
            count: (0, 1, 1),
        };
        let err = volume_ssd_map_range(output, patch, empty).unwrap_err().to_string();
        assert!(err.contains("offset range"), "{err}");
    }

    #[test]
    fn a_depth_one_volume_is_an_image() {
        let mut rng = Rng::new(5);
        let out = random(&mut rng, 6 * 4 * 3);
        let pat = random(&mut rng, 3 * 3 * 3);
        let view = |data: &'static [f32], w, h| VolumeView {
            data,
            width: w,
            height: h,
            depth: 1,
            channels: 3,
            weights: None,
        };
        let out: &'static [f32] = Box::leak(out.into_boxed_slice());
        let pat: &'static [f32] = Box::leak(pat.into_boxed_slice());
        let map = volume_ssd_map(view(out, 6, 4), view(pat, 3, 3)).unwrap();
        let image = |d: &[f32], w, h| crate::core::Image::from_vec(w, h, 3, d.to_vec()).unwrap();
        let flat = super::super::ssd_map(
            &image(out, 6, 4),
            None,
            &image(pat, 3, 3),
            None,
            super::super::Boundary::Open,
        )
        .unwrap();
        for (a, b) in map.costs.iter().zip(flat.costs()) {
            assert!((a - b).abs() < 1e-4);
        }
    }

    #[test]
    fn bad_volumes_are_named_errors() {
        let data = vec![0.0f32; 10];
        let bad = VolumeView {
            data: &data,
            width: 2,
            height: 2,
            depth: 2,
            channels: 3,
            weights: None,
        };
        let err = volume_ssd_map(bad, bad).unwrap_err().to_string();
        assert!(err.contains("output volume"), "{err}");
    }
}
