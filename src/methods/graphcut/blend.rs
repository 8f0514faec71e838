//! Hiding seams in the final image (section 5): feathering, a Gaussian-weighted mix of the patches
//! meeting near a seam, and Burt & Adelson's multi-resolution splining, which blends each band of
//! a Laplacian pyramid across the cut with a correspondingly blurred mask.

use super::canvas::{Patch, UNCOVERED};
use super::synthesis::Synthesis;
use crate::core::pyramid::gaussian_pyramid;
use crate::core::sample::resize_bilinear;
use crate::core::{Edge, Image, Result};

/// Radius of the feathering window; the Gaussian has sigma = radius / 2.
pub const FEATHER_RADIUS: usize = 3;
/// Pyramid levels of the multi-resolution spline.
pub const SPLINE_LEVELS: usize = 4;

/// A grid of labelled cells, pixels or voxels, whose seams [`feather`] hides: images and video
/// share one feathering.
pub trait FeatherGrid {
    /// The grid's extent along x, y and t (1 for an image).
    fn extent(&self) -> [usize; 3];
    /// Values per cell.
    fn channels(&self) -> usize;
    /// The label of cell `i` ([`UNCOVERED`] where none).
    fn label(&self, i: usize) -> u32;
    /// Coordinate `c` along `axis`, brought inside the grid as its border says (wrapped or
    /// clamped).
    fn resolve(&self, axis: usize, c: isize) -> usize;
    /// What the patch of `label` shows at cell `i`, or the output's own value where it does not
    /// reach.
    fn value(&self, label: u32, i: usize) -> &[f32];
}

/// Feathering (section 5): a cell near a seam becomes the average of what each nearby cell's
/// patch shows at it, weighted by a Gaussian of the distance to that nearby cell, over a window
/// of [`FEATHER_RADIUS`] along every axis the grid has (time too, for video: a seam in time is
/// a seam). Away from seams every nearby cell has the same patch and the cell is unchanged.
/// `out` holds the grid's values, `channels` per cell, and is changed where cells mix.
pub fn feather<G: FeatherGrid>(grid: &G, out: &mut [f32]) {
    let [w, h, d] = grid.extent();
    let c = grid.channels();
    let r = FEATHER_RADIUS as isize;
    let rt = if d > 1 { r } else { 0 };
    let sigma2 = (FEATHER_RADIUS as f32 / 2.0).powi(2);
    let mut acc = [0.0f32; 4];
    for t in 0..d {
        for y in 0..h {
            for x in 0..w {
                let i = (t * h + y) * w + x;
                let own = grid.label(i);
                if own == UNCOVERED {
                    continue;
                }
                let mut mixed = false;
                acc[..c].iter_mut().for_each(|v| *v = 0.0);
                let mut total = 0.0;
                for dt in -rt..=rt {
                    let nt = grid.resolve(2, t as isize + dt);
                    for dy in -r..=r {
                        let ny = grid.resolve(1, y as isize + dy);
                        for dx in -r..=r {
                            let nx = grid.resolve(0, x as isize + dx);
                            let label = grid.label((nt * h + ny) * w + nx);
                            if label == UNCOVERED {
                                continue;
                            }
                            mixed |= label != own;
                            let g = crate::core::math::expf(
                                -((dx * dx + dy * dy + dt * dt) as f32) / (2.0 * sigma2),
                            );
                            let value = grid.value(label, i);
                            for k in 0..c {
                                acc[k] += g * value[k];
                            }
                            total += g;
                        }
                    }
                }
                if mixed {
                    for (v, sum) in out[i * c..(i + 1) * c].iter_mut().zip(&acc) {
                        *v = sum / total;
                    }
                }
            }
        }
    }
}

/// The output's pixels as a feathering grid.
impl FeatherGrid for Synthesis {
    fn extent(&self) -> [usize; 3] {
        [self.canvas.width, self.canvas.height, 1]
    }

    fn channels(&self) -> usize {
        self.canvas.pixels.channels()
    }

    fn label(&self, i: usize) -> u32 {
        self.canvas.label[i]
    }

    fn resolve(&self, axis: usize, c: isize) -> usize {
        let edge = if self.canvas.wrap {
            Edge::Wrap
        } else {
            Edge::Clamp
        };
        match axis {
            0 => edge.resolve(c, self.canvas.width),
            1 => edge.resolve(c, self.canvas.height),
            _ => 0,
        }
    }

    fn value(&self, label: u32, i: usize) -> &[f32] {
        self.patch_value(self.canvas.patches[label as usize], i)
    }
}

impl Synthesis {
    /// The value patch `patch` shows at pixel `i`, or the output's own where it does not reach.
    fn patch_value(&self, patch: Patch, i: usize) -> &[f32] {
        match self.sample(patch, i, true) {
            Some(sample) => sample.colour,
            None => {
                let w = self.canvas.width;
                self.canvas.pixels.pixel(i % w, i / w)
            }
        }
    }

    /// Feathering ([`feather`]) of the output's seams.
    pub fn feathered(&self) -> Image {
        let mut out = self.canvas.pixels.clone();
        feather(self, out.data_mut());
        out
    }

    /// Multi-resolution splining: every patch present in the output contributes its Laplacian
    /// pyramid weighted by the Gaussian pyramid of its cut mask; the bands are summed and
    /// collapsed. Where a patch does not reach, it shows the output itself, so its pyramid has
    /// no false edges there.
    pub fn splined(&self) -> Result<Image> {
        let (w, h, c) = (
            self.canvas.width,
            self.canvas.height,
            self.canvas.pixels.channels(),
        );
        let edge = if self.canvas.wrap {
            Edge::Wrap
        } else {
            Edge::Clamp
        };
        let mut present: Vec<u32> = self
            .canvas
            .label
            .iter()
            .copied()
            .filter(|&l| l != UNCOVERED)
            .collect();
        present.sort_unstable();
        present.dedup();
        let levels =
            SPLINE_LEVELS.min(1 + crate::core::math::log2f(w.min(h) as f32).floor() as usize);
        let mut bands: Vec<Image> = gaussian_pyramid(&self.canvas.pixels, levels, edge)?
            .iter()
            .map(|l| Image::new(l.width(), l.height(), c))
            .collect::<Result<_>>()?;
        for &label in &present {
            let patch = self.canvas.patches[label as usize];
            let mut image = self.canvas.pixels.clone();
            for i in 0..w * h {
                image.data_mut()[i * c..(i + 1) * c].copy_from_slice(self.patch_value(patch, i));
            }
            let mask_data: Vec<f32> = self
                .canvas
                .label
                .iter()
                .map(|&l| if l == label { 1.0 } else { 0.0 })
                .collect();
            let mask = Image::from_vec(w, h, 1, mask_data)?;
            let gaussians = gaussian_pyramid(&image, levels, edge)?;
            let masks = gaussian_pyramid(&mask, levels, edge)?;
            for k in 0..levels {
                // Laplacian band: this level minus the next one up-sampled (the top keeps the rest).
                let band = if k + 1 < levels {
                    let up = resize_bilinear(
                        &gaussians[k + 1],
                        gaussians[k].width(),
                        gaussians[k].height(),
                        edge,
                    )?;
                    subtract(&gaussians[k], &up)
                } else {
                    gaussians[k].clone()
                };
                let m = masks[k].data();
                for (p, (dst, src)) in bands[k]
                    .data_mut()
                    .chunks_exact_mut(c)
                    .zip(band.data().chunks_exact(c))
                    .enumerate()
                {
                    for (d, s) in dst.iter_mut().zip(src) {
                        *d += m[p] * s;
                    }
                }
            }
        }
        // Collapse from the coarsest band.
        let mut image = bands.pop().expect("at least one level");
        while let Some(band) = bands.pop() {
            let up = resize_bilinear(&image, band.width(), band.height(), edge)?;
            image = add(&band, &up);
        }
        Ok(image)
    }
}

fn subtract(a: &Image, b: &Image) -> Image {
    let data = a.data().iter().zip(b.data()).map(|(x, y)| x - y).collect();
    Image::from_vec(a.width(), a.height(), a.channels(), data).expect("same size")
}

fn add(a: &Image, b: &Image) -> Image {
    let data = a.data().iter().zip(b.data()).map(|(x, y)| x + y).collect();
    Image::from_vec(a.width(), a.height(), a.channels(), data).expect("same size")
}
