//! Stage 2 of Shen et al. 2009: local deformation with a brush. The designer paints roughly over
//! texture elements of a reference texture; the sub-image I_s enclosing the stroke is clipped
//! out, placed on the base where the designer drags it, labelled by the two-label graph cut
//! (`labelling`) and pasted in the gradient domain (`poisson_paste`). Stroke after stroke, each
//! undoable. Adding elements (brush them from a reference) and removing them (brush plain
//! background over them) is the density control of Figs. 1 and 12.

use super::labelling::{LabelImage, LabellingWeights, Pin, Problem};
use super::poisson_paste;
use crate::core::{Error, Image, Result};
use crate::solvers::maxflow::Graph;

pub use super::memory::UNDO_BUDGET_BYTES;

/// Options of the brush.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BrushOptions {
    /// Weights nu, k1 and k2 of the labelling energy (eqs. 1-3). Default: 1000, 0.5, 0.5.
    pub weights: LabellingWeights,
    /// Pixels of reference around the stroke's bounding box that I_s takes, so that the cut
    /// has room to find a seam where base and reference agree. Default: 12.
    pub margin: usize,
    /// Gradient-domain paste (true) or the plain cut-and-paste of the labelling. Default: true.
    pub poisson: bool,
    /// The memory budget in MiB (see `crate::core::budget`): a base whose working set would
    /// exceed it is refused. Default: 1024.
    pub memory_budget_mib: usize,
}

impl Default for BrushOptions {
    fn default() -> Self {
        BrushOptions {
            weights: LabellingWeights::default(),
            margin: 12,
            poisson: true,
            memory_budget_mib: crate::core::budget::DEFAULT_MEMORY_BUDGET_MIB,
        }
    }
}

impl BrushOptions {
    /// Checks every option: weights finite and >= 0 (nu at most 1e9), margin at most 256.
    pub fn validate(&self) -> Result<()> {
        self.weights.validate()?;
        if self.margin > 256 {
            return Err(Error::InvalidParameter {
                name: "margin",
                reason: format!("must be at most 256 pixels, got {}", self.margin),
            });
        }
        Ok(())
    }
}

/// A stroke: a mask over the reference (true where painted) and the offset that carries a
/// reference pixel (x, y) to the base pixel (x + dx, y + dy).
pub struct Stroke<'a> {
    /// The reference texture the designer paints over.
    pub reference: &'a Image,
    /// True where painted: one value per reference pixel, row by row.
    pub mask: &'a [bool],
    /// Horizontal offset from the reference to the base, in pixels.
    pub dx: isize,
    /// Vertical offset from the reference to the base, in pixels.
    pub dy: isize,
}

/// What one stroke did.
#[derive(Debug, Clone, PartialEq)]
pub struct StrokeResult {
    /// The window on the base that the cut worked on.
    pub x: usize,
    /// Top of that window.
    pub y: usize,
    /// Width of that window.
    pub width: usize,
    /// Height of that window.
    pub height: usize,
    /// Per window pixel: 0 kept the base, 1 took I_s, 2 took I_s and was brushed (Fig. 3e).
    pub labels: Vec<u8>,
    /// Pixels that took I_s.
    pub taken: usize,
    /// E(L) of eq. 1 at the minimum.
    pub energy: f64,
    /// Conjugate-gradient iterations of the paste (0 without Poisson).
    pub poisson_iterations: usize,
}

/// A base texture being deformed locally, with its undo history.
pub struct LocalDeformation {
    base: Image,
    options: BrushOptions,
    history: Vec<Image>,
    graph: Graph,
}

impl LocalDeformation {
    /// A brush on a copy of `base`; fails on a bad option or a base beyond the memory budget.
    pub fn new(base: &Image, options: BrushOptions) -> Result<Self> {
        options.validate()?;
        crate::core::budget::validate_budget(options.memory_budget_mib)?;
        let (w, h) = (base.width(), base.height());
        super::memory::brush_working_set((w, h, base.channels())).check(
            &format!("base {w}x{h}"),
            super::memory::BRUSH,
            options.memory_budget_mib,
        )?;
        Ok(LocalDeformation {
            base: base.clone(),
            options,
            history: Vec::new(),
            graph: Graph::new(1)?,
        })
    }

    /// The estimated working set (see `super::memory`).
    #[must_use]
    pub fn working_set(&self) -> crate::core::budget::WorkingSet {
        let b = &self.base;
        super::memory::brush_working_set((b.width(), b.height(), b.channels()))
    }

    /// The base as it is now.
    #[must_use]
    pub fn image(&self) -> &Image {
        &self.base
    }

    /// Strokes that can be undone.
    #[must_use]
    pub fn undo_depth(&self) -> usize {
        self.history.len()
    }

    /// The weights of the labelling energy for the strokes to come; the base, the strokes made
    /// and the undo history stay. Fails (changing nothing) on a bad weight.
    pub fn set_weights(&mut self, weights: LabellingWeights) -> Result<()> {
        weights.validate()?;
        self.options.weights = weights;
        Ok(())
    }

    /// The options the next stroke uses.
    #[must_use]
    pub fn options(&self) -> &BrushOptions {
        &self.options
    }

    /// Goes back one stroke; false if there is none.
    pub fn undo(&mut self) -> bool {
        match self.history.pop() {
            Some(previous) => {
                self.base = previous;
                true
            }
            None => false,
        }
    }

    /// Applies one stroke. The base is unchanged if it fails.
    pub fn stroke(&mut self, stroke: &Stroke<'_>) -> Result<StrokeResult> {
        let reference = stroke.reference;
        let (rw, rh) = (reference.width(), reference.height());
        if stroke.mask.len() != rw * rh {
            return Err(Error::LengthMismatch {
                what: "stroke mask",
                expected: rw * rh,
                actual: stroke.mask.len(),
            });
        }
        // A colour reference on a grey base makes the base colour (and the other way round the
        // reference is promoted): nothing the designer brushes loses its colour.
        let channels = reference.channels().max(self.base.channels());
        let promoted;
        let reference = if reference.channels() == channels {
            reference
        } else {
            promoted = reference.with_channels(channels)?;
            &promoted
        };
        let base_image = if self.base.channels() == channels {
            self.base.clone()
        } else {
            self.base.with_channels(channels)?
        };
        let limit = 1isize << 20;
        if stroke.dx.abs() > limit || stroke.dy.abs() > limit {
            return Err(Error::InvalidParameter {
                name: "stroke offset",
                reason: format!("({}, {}) is absurdly far", stroke.dx, stroke.dy),
            });
        }
        // The stroke's bounding box, grown by the margin and clipped to the reference: I_s.
        let painted = stroke
            .mask
            .iter()
            .enumerate()
            .filter(|(_, m)| **m)
            .map(|(i, _)| i);
        let (mut x0, mut y0, mut x1, mut y1) = (usize::MAX, usize::MAX, 0, 0);
        for i in painted {
            let (x, y) = (i % rw, i / rw);
            (x0, y0, x1, y1) = (x0.min(x), y0.min(y), x1.max(x), y1.max(y));
        }
        if x0 == usize::MAX {
            return Err(Error::InvalidParameter {
                name: "stroke mask",
                reason: "paints no pixel".into(),
            });
        }
        let m = self.options.margin;
        let (sx0, sy0) = (x0.saturating_sub(m), y0.saturating_sub(m));
        let (sx1, sy1) = ((x1 + m).min(rw - 1), (y1 + m).min(rh - 1));
        // I_s placed on the base, clipped to the base: the window.
        let (bw, bh) = (self.base.width() as isize, self.base.height() as isize);
        let wx0 = (sx0 as isize + stroke.dx).max(0);
        let wy0 = (sy0 as isize + stroke.dy).max(0);
        let wx1 = (sx1 as isize + stroke.dx).min(bw - 1);
        let wy1 = (sy1 as isize + stroke.dy).min(bh - 1);
        if wx1 < wx0 || wy1 < wy0 {
            return Err(Error::InvalidParameter {
                name: "stroke offset",
                reason: format!(
                    "({}, {}) moves the stroke off the {bw}x{bh} base",
                    stroke.dx, stroke.dy
                ),
            });
        }
        let (wx0, wy0) = (wx0 as usize, wy0 as usize);
        let (ww, wh) = (wx1 as usize - wx0 + 1, wy1 as usize - wy0 + 1);
        let c = channels;
        let to_reference = |x: usize, y: usize| {
            (
                (x as isize + wx0 as isize - stroke.dx) as usize,
                (y as isize + wy0 as isize - stroke.dy) as usize,
            )
        };
        let source = window(reference, ww, wh, to_reference);
        let base = window(&base_image, ww, wh, |x, y| (x + wx0, y + wy0));
        // A window side that lies inside the base is enclosed by base texture; a side on the
        // base's own edge is not (nothing lies beyond it to meet).
        let pins: Vec<Pin> = (0..ww * wh)
            .map(|i| {
                let (x, y) = (i % ww, i / ww);
                let (rx, ry) = to_reference(x, y);
                let on_border = (x == 0 && wx0 > 0)
                    || (y == 0 && wy0 > 0)
                    || (x == ww - 1 && wx0 + ww < self.base.width())
                    || (y == wh - 1 && wy0 + wh < self.base.height());
                if stroke.mask[ry * rw + rx] && !on_border {
                    Pin::Stroke
                } else if on_border {
                    Pin::Base
                } else {
                    Pin::Free
                }
            })
            .collect();
        if !pins.contains(&Pin::Stroke) {
            return Err(Error::InvalidParameter {
                name: "stroke",
                reason: "no painted pixel lands inside the base at this offset".into(),
            });
        }
        let problem = Problem {
            width: ww,
            height: wh,
            channels: c,
            source: &source,
            base: &base,
            pins: &pins,
            weights: self.options.weights,
        };
        let (labels, energy) = problem.solve(&mut self.graph)?;
        let mut pasted = base.colour.clone();
        let poisson_iterations = if self.options.poisson {
            poisson_paste::paste(ww, wh, c, &source.colour, &labels, &mut pasted)
        } else {
            for (i, _) in labels.iter().enumerate().filter(|(_, l)| **l) {
                pasted[i * c..(i + 1) * c].copy_from_slice(&source.colour[i * c..(i + 1) * c]);
            }
            0
        };
        let mut next = base_image;
        for y in 0..wh {
            for x in 0..ww {
                let i = y * ww + x;
                next.pixel_mut(wx0 + x, wy0 + y)
                    .copy_from_slice(&pasted[i * c..(i + 1) * c]);
            }
        }
        let previous = std::mem::replace(&mut self.base, next);
        self.push_history(previous);
        let labels: Vec<u8> = labels
            .iter()
            .zip(&pins)
            .map(|(&l, &p)| match (l, p) {
                (false, _) => 0,
                (true, Pin::Stroke) => 2,
                (true, _) => 1,
            })
            .collect();
        Ok(StrokeResult {
            x: wx0,
            y: wy0,
            width: ww,
            height: wh,
            taken: labels.iter().filter(|&&l| l > 0).count(),
            labels,
            energy,
            poisson_iterations,
        })
    }

    fn push_history(&mut self, image: Image) {
        let bytes = image.data().len() * 4;
        self.history.push(image);
        while self.history.len() > 1 && self.history.len() * bytes > UNDO_BUDGET_BYTES {
            self.history.remove(0);
        }
    }
}

/// The colours and 6-component gradients (forward differences, zero past the image's edge) of
/// the `w` x `h` window whose pixel (x, y) is `image`'s pixel `at(x, y)`.
fn window(
    image: &Image,
    w: usize,
    h: usize,
    at: impl Fn(usize, usize) -> (usize, usize),
) -> LabelImage {
    let c = image.channels();
    let (iw, ih) = (image.width(), image.height());
    let mut colour = Vec::with_capacity(w * h * c);
    let mut gradient = Vec::with_capacity(w * h * 2 * c);
    for y in 0..h {
        for x in 0..w {
            let (ix, iy) = at(x, y);
            let here = image.pixel(ix, iy);
            colour.extend_from_slice(here);
            let right = image.pixel((ix + 1).min(iw - 1), iy);
            let down = image.pixel(ix, (iy + 1).min(ih - 1));
            gradient.extend(right.iter().zip(here).map(|(a, b)| a - b));
            gradient.extend(down.iter().zip(here).map(|(a, b)| a - b));
        }
    }
    LabelImage { colour, gradient }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::testing::{noise, sample};

    fn disc_mask(w: usize, h: usize, cx: f32, cy: f32, r: f32) -> Vec<bool> {
        (0..w * h)
            .map(|i| {
                let (x, y) = ((i % w) as f32 - cx, (i / w) as f32 - cy);
                x * x + y * y <= r * r
            })
            .collect()
    }

    #[test]
    fn a_stroke_takes_the_brushed_elements_and_undo_restores_the_base() {
        let base = sample("gravel_64").with_channels(3).unwrap();
        let reference = sample("paving_64").with_channels(3).unwrap();
        let mut design = LocalDeformation::new(&base, BrushOptions::default()).unwrap();
        let mask = disc_mask(64, 64, 30.0, 30.0, 6.0);
        let result = design
            .stroke(&Stroke {
                reference: &reference,
                mask: &mask,
                dx: 5,
                dy: -3,
            })
            .unwrap();
        assert_eq!((result.x, result.y), (30 - 6 - 12 + 5, 30 - 6 - 12 - 3));
        assert!(result.taken >= mask.iter().filter(|&&m| m).count());
        assert!(
            result.labels.iter().filter(|&&l| l == 2).count()
                == mask.iter().filter(|&&m| m).count()
        );
        // Outside the window the base is untouched; inside the stroke the result solves the
        // Poisson equation: its Laplacian is the reference's.
        let out = design.image();
        assert_eq!(out.pixel(0, 63), base.pixel(0, 63));
        let laplacian = |img: &Image, x: usize, y: usize| {
            img.pixel(x + 1, y)[1]
                + img.pixel(x - 1, y)[1]
                + img.pixel(x, y + 1)[1]
                + img.pixel(x, y - 1)[1]
                - 4.0 * img.pixel(x, y)[1]
        };
        for (x, y) in [(30, 30), (28, 31), (33, 29)] {
            let (got, want) = (laplacian(out, x + 5, y - 3), laplacian(&reference, x, y));
            assert!((got - want).abs() < 2e-3, "({x}, {y}): {got} vs {want}");
        }
        assert_ne!(out, &base);
        assert_eq!(design.undo_depth(), 1);
        assert!(design.undo());
        assert_eq!(design.image(), &base);
        assert!(!design.undo());
    }

    /// A new nu applies to the next stroke and keeps the strokes made and their undo: at the
    /// default every brushed pixel is taken, with nu 0 keeping the base costs a brushed pixel
    /// nothing and the cut takes fewer.
    #[test]
    fn new_weights_keep_the_strokes_and_apply_to_the_next() {
        let base = sample("gravel_64").with_channels(3).unwrap();
        let reference = sample("paving_64").with_channels(3).unwrap();
        let mut design = LocalDeformation::new(&base, BrushOptions::default()).unwrap();
        let mask = disc_mask(64, 64, 30.0, 30.0, 6.0);
        let stroke = |d: &mut LocalDeformation, dx| {
            d.stroke(&Stroke {
                reference: &reference,
                mask: &mask,
                dx,
                dy: 0,
            })
            .unwrap()
        };
        let first = stroke(&mut design, -12);
        let after_first = design.image().clone();
        let weights = design.options().weights;
        let bad = LabellingWeights {
            nu: f32::NAN,
            ..weights
        };
        assert!(design.set_weights(bad).unwrap_err().to_string().contains("nu"));
        assert_eq!(design.options().weights, weights);
        design
            .set_weights(LabellingWeights { nu: 0.0, ..weights })
            .unwrap();
        assert_eq!(design.image(), &after_first);
        assert_eq!(design.undo_depth(), 1);
        let second = stroke(&mut design, 12);
        let brushed = mask.iter().filter(|&&m| m).count();
        assert!(first.taken >= brushed, "nu {}: {} of {brushed}", weights.nu, first.taken);
        assert!(second.taken < brushed, "nu 0: {} of {brushed}", second.taken);
        assert_eq!(design.undo_depth(), 2);
        assert!(design.undo());
        assert_eq!(design.image(), &after_first);
    }

    #[test]
    fn the_base_stays_when_a_stroke_is_bad() {
        let base = noise(32, 32, 3, 1);
        let reference = noise(32, 32, 3, 2);
        let mut design = LocalDeformation::new(&base, BrushOptions::default()).unwrap();
        let empty = vec![false; 32 * 32];
        let err = |d: &mut LocalDeformation, mask: &[bool], dx: isize| {
            d.stroke(&Stroke {
                reference: &reference,
                mask,
                dx,
                dy: 0,
            })
            .unwrap_err()
            .to_string()
        };
        assert!(err(&mut design, &empty, 0).contains("paints no pixel"));
        assert!(err(&mut design, &[true; 5], 0).contains("stroke mask has length 5"));
        let mask = disc_mask(32, 32, 16.0, 16.0, 3.0);
        assert!(err(&mut design, &mask, 100).contains("off the 32x32 base"));
        assert_eq!(design.image(), &base);
        assert_eq!(design.undo_depth(), 0);
    }

    #[test]
    fn a_stroke_on_the_base_edge_reaches_it() {
        let base = noise(32, 32, 3, 4);
        let reference = noise(32, 32, 3, 5);
        let mut design = LocalDeformation::new(&base, BrushOptions::default()).unwrap();
        let mask = disc_mask(32, 32, 0.0, 0.0, 4.0);
        let r = design
            .stroke(&Stroke {
                reference: &reference,
                mask: &mask,
                dx: 0,
                dy: 0,
            })
            .unwrap();
        assert_eq!((r.x, r.y), (0, 0));
        assert_eq!(r.labels[0], 2, "the corner pixel was brushed and is taken");
    }
}
