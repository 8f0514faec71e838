//! Stage 1 of Shen et al. 2009: global deformations of the sample (rotation, translation, mirror,
//! scale and flip), each giving a new small texture I_g.
//!
//! None of them invents content. Rotation by a multiple of 90 degrees, mirror, flip and the cyclic
//! shift move pixels without resampling, so they are exact (mirror twice is the identity; a
//! quarter turn is a transpose plus a flip). Any other angle resamples bicubically and keeps only
//! the largest axis-aligned rectangle inside the rotated sample, shrunk so that every bicubic tap
//! lies inside the source: no pixel is read from past the border. Scaling keeps the pixels whose
//! centres map inside the source, and shrinks by area averaging so that nothing aliases.

use crate::core::sample::{sample_bicubic, shrink_area};
use crate::core::{Edge, Error, Image, Result, math};

/// The smallest side a deformed texture may have: a neighbourhood of the syntheses must fit.
pub const MIN_SIDE: usize = 8;
/// Scale factors accepted (a quarter to four times the size).
pub const SCALE_RANGE: (f64, f64) = (0.25, 4.0);
/// Most deformed textures one range may ask for.
pub const MAX_DEFORMATIONS: usize = 64;

/// One global deformation of a texture.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Deformation {
    /// Rotation by `degrees`, counter-clockwise as seen on screen.
    Rotate {
        /// Angle in degrees, any finite value; multiples of 90 are exact.
        degrees: f64,
    },
    /// Cyclic translation: pixel (x, y) moves to (x + dx, y + dy) modulo the size.
    Shift {
        /// Horizontal shift in pixels, to the right.
        dx: isize,
        /// Vertical shift in pixels, downwards.
        dy: isize,
    },
    /// Left-right reflection.
    Mirror,
    /// Top-bottom reflection.
    Flip,
    /// Resize by `factor` in both directions.
    Scale {
        /// Scale factor, 0.25 to 4 ([`SCALE_RANGE`]); below 1 shrinks by area averaging.
        factor: f64,
    },
}

impl Deformation {
    /// A short name for galleries and captions, e.g. "rotate 30°".
    #[must_use]
    pub fn label(&self) -> String {
        match *self {
            Deformation::Rotate { degrees } => format!("rotate {degrees}°"),
            Deformation::Shift { dx, dy } => format!("shift {dx},{dy}"),
            Deformation::Mirror => "mirror".into(),
            Deformation::Flip => "flip".into(),
            Deformation::Scale { factor } => format!("scale {factor}x"),
        }
    }

    /// Checks the parameter (finite, in range).
    pub fn validate(&self) -> Result<()> {
        match *self {
            Deformation::Rotate { degrees } if !degrees.is_finite() => {
                Err(Error::InvalidParameter {
                    name: "rotation",
                    reason: format!("must be a finite number of degrees, got {degrees}"),
                })
            }
            Deformation::Scale { factor } if !(SCALE_RANGE.0..=SCALE_RANGE.1).contains(&factor) => {
                Err(Error::InvalidParameter {
                    name: "scale",
                    reason: format!(
                        "must be between {} and {}, got {factor}",
                        SCALE_RANGE.0, SCALE_RANGE.1
                    ),
                })
            }
            _ => Ok(()),
        }
    }

    /// The deformed texture.
    pub fn apply(&self, image: &Image) -> Result<Image> {
        self.validate()?;
        let out = match *self {
            Deformation::Rotate { degrees } => rotate(image, degrees)?,
            Deformation::Shift { dx, dy } => shift(image, dx, dy),
            Deformation::Mirror => remap(image, image.width(), image.height(), |x, y, w, _| {
                (w - 1 - x, y)
            }),
            Deformation::Flip => remap(image, image.width(), image.height(), |x, y, _, h| {
                (x, h - 1 - y)
            }),
            Deformation::Scale { factor } => scale(image, factor)?,
        };
        if out.width() < MIN_SIDE.min(image.width()) || out.height() < MIN_SIDE.min(image.height())
        {
            return Err(Error::InvalidSize {
                what: "deformed texture",
                width: out.width(),
                height: out.height(),
                reason: format!(
                    "{} of a {}x{} sample leaves less than {MIN_SIDE} pixels a side",
                    self.label(),
                    image.width(),
                    image.height()
                ),
            });
        }
        Ok(out)
    }
}

/// Applies the deformations in order.
pub fn deform(image: &Image, deformations: &[Deformation]) -> Result<Image> {
    let mut out = image.clone();
    for d in deformations {
        out = d.apply(&out)?;
    }
    Ok(out)
}

/// An inclusive range `from..=to` walked in steps of `step`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Steps {
    /// First value.
    pub from: f64,
    /// Last value, included when the steps reach it; at least `from`.
    pub to: f64,
    /// Step between values, greater than 0.
    pub step: f64,
}

impl Steps {
    fn values(&self, name: &'static str) -> Result<Vec<f64>> {
        for v in [self.from, self.to, self.step] {
            if !v.is_finite() {
                return Err(Error::InvalidParameter {
                    name,
                    reason: format!("from, to and step must be finite numbers, got {v}"),
                });
            }
        }
        if self.step <= 0.0 || self.to < self.from {
            return Err(Error::InvalidParameter {
                name,
                reason: format!(
                    "needs step > 0 and to >= from, got from {} to {} step {}",
                    self.from, self.to, self.step
                ),
            });
        }
        let count = ((self.to - self.from) / self.step + 1e-9).floor() as usize + 1;
        if count > MAX_DEFORMATIONS {
            return Err(Error::InvalidParameter {
                name,
                reason: format!("asks for {count} textures, at most {MAX_DEFORMATIONS}"),
            });
        }
        Ok((0..count)
            .map(|i| self.from + i as f64 * self.step)
            .collect())
    }
}

/// The user's ranges for stage 1: every value of each range gives one deformed texture.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct DeformationRanges {
    /// Angles in degrees.
    pub rotation: Option<Steps>,
    /// Scale factors.
    pub scale: Option<Steps>,
    /// Cyclic shifts as a fraction of the size, applied along both axes.
    pub shift: Option<Steps>,
    /// Also the mirrored (left-right reflected) texture.
    pub mirror: bool,
    /// Also the flipped (top-bottom reflected) texture.
    pub flip: bool,
}

impl DeformationRanges {
    /// The deformations the ranges name, in the order rotation, scale, shift, mirror, flip. The
    /// identity values (0 degrees, scale 1, shift 0) are left out: the sample itself is I.
    pub fn expand(&self, width: usize, height: usize) -> Result<Vec<Deformation>> {
        let mut out = Vec::new();
        if let Some(r) = &self.rotation {
            out.extend(
                r.values("rotation")?
                    .into_iter()
                    .filter(|d| d.rem_euclid(360.0) != 0.0)
                    .map(|degrees| Deformation::Rotate { degrees }),
            );
        }
        if let Some(s) = &self.scale {
            for factor in s.values("scale")? {
                if factor != 1.0 {
                    let d = Deformation::Scale { factor };
                    d.validate()?;
                    out.push(d);
                }
            }
        }
        if let Some(s) = &self.shift {
            for f in s.values("shift")? {
                let (dx, dy) = (
                    (f * width as f64).round() as isize,
                    (f * height as f64).round() as isize,
                );
                if dx.rem_euclid(width as isize) != 0 || dy.rem_euclid(height as isize) != 0 {
                    out.push(Deformation::Shift { dx, dy });
                }
            }
        }
        if self.mirror {
            out.push(Deformation::Mirror);
        }
        if self.flip {
            out.push(Deformation::Flip);
        }
        if out.len() > MAX_DEFORMATIONS {
            return Err(Error::InvalidParameter {
                name: "deformation ranges",
                reason: format!("ask for {} textures, at most {MAX_DEFORMATIONS}", out.len()),
            });
        }
        Ok(out)
    }
}

/// A `w` x `h` image whose pixel (x, y) is `image`'s pixel `source(x, y, width, height)`.
fn remap(
    image: &Image,
    w: usize,
    h: usize,
    source: impl Fn(usize, usize, usize, usize) -> (usize, usize),
) -> Image {
    let (iw, ih, c) = (image.width(), image.height(), image.channels());
    let mut data = Vec::with_capacity(w * h * c);
    for y in 0..h {
        for x in 0..w {
            let (sx, sy) = source(x, y, iw, ih);
            data.extend_from_slice(image.pixel(sx, sy));
        }
    }
    Image::from_vec(w, h, c, data).expect("sizes come from a valid image")
}

fn shift(image: &Image, dx: isize, dy: isize) -> Image {
    let (w, h) = (image.width(), image.height());
    remap(image, w, h, |x, y, w, h| {
        (
            (x as isize - dx).rem_euclid(w as isize) as usize,
            (y as isize - dy).rem_euclid(h as isize) as usize,
        )
    })
}

/// The transpose: pixel (x, y) moves to (y, x).
#[must_use]
pub fn transpose(image: &Image) -> Image {
    remap(image, image.height(), image.width(), |x, y, _, _| (y, x))
}

/// Exact quarter turns: 1 = 90 degrees counter-clockwise (a transpose, then a flip).
fn quarter_turns(image: &Image, turns: usize) -> Image {
    let (w, h) = (image.width(), image.height());
    match turns % 4 {
        0 => image.clone(),
        1 => remap(image, h, w, |x, y, w, _| (w - 1 - y, x)),
        2 => remap(image, w, h, |x, y, w, h| (w - 1 - x, h - 1 - y)),
        _ => remap(image, h, w, |x, y, _, h| (y, h - 1 - x)),
    }
}

/// Width and height of the largest axis-aligned rectangle inside a `w` x `h` rectangle turned by
/// `angle` radians. When the short side is small against the long one the best rectangle touches
/// the long sides only (a "thin" case); otherwise its four corners touch the four sides, which is
/// a 2x2 linear system in its half-sizes.
#[must_use]
pub fn inscribed_size(w: f64, h: f64, angle: f64) -> (f64, f64) {
    if w <= 0.0 || h <= 0.0 {
        return (0.0, 0.0);
    }
    let (s, c) = (math::sin(angle).abs(), math::cos(angle).abs());
    let (long, short) = if w >= h { (w, h) } else { (h, w) };
    if short <= 2.0 * s * c * long || (s - c).abs() < 1e-10 {
        let half = 0.5 * short;
        if w >= h {
            (half / s.max(1e-12), half / c.max(1e-12))
        } else {
            (half / c.max(1e-12), half / s.max(1e-12))
        }
    } else {
        let cos2 = c * c - s * s;
        ((w * c - h * s) / cos2, (h * c - w * s) / cos2)
    }
}

fn rotate(image: &Image, degrees: f64) -> Result<Image> {
    let turns = degrees / 90.0;
    if turns == turns.round() {
        return Ok(quarter_turns(image, turns.rem_euclid(4.0) as usize));
    }
    let (w, h) = (image.width(), image.height());
    // Bicubic taps reach one pixel beyond the sample point and one more past it: keep every
    // sample point at least 1 pixel inside so all 16 taps are real pixels.
    let (valid_w, valid_h) = (w as f64 - 3.0, h as f64 - 3.0);
    let angle = degrees.to_radians();
    let (rw, rh) = inscribed_size(valid_w, valid_h, angle);
    let (ow, oh) = (rw.floor().max(0.0) as usize, rh.floor().max(0.0) as usize);
    if ow == 0 || oh == 0 {
        return Err(Error::InvalidSize {
            what: "rotated texture",
            width: ow,
            height: oh,
            reason: format!("a {w}x{h} sample turned by {degrees}° keeps no whole pixel"),
        });
    }
    let (sin, cos) = (math::sin(angle), math::cos(angle));
    let (scx, scy) = ((w as f64 - 1.0) / 2.0, (h as f64 - 1.0) / 2.0);
    let (ocx, ocy) = ((ow as f64 - 1.0) / 2.0, (oh as f64 - 1.0) / 2.0);
    let c = image.channels();
    let mut out = Image::new(ow, oh, c)?;
    let mut px = [0.0f32; 4];
    for y in 0..oh {
        for x in 0..ow {
            // Counter-clockwise on screen (y down): the output's offset (u, v) came from the
            // source offset turned clockwise, i.e. by -angle in screen coordinates.
            let (u, v) = (x as f64 - ocx, y as f64 - ocy);
            let sx = scx + cos * u - sin * v;
            let sy = scy + sin * u + cos * v;
            sample_bicubic(image, sx as f32, sy as f32, Edge::Clamp, &mut px);
            out.pixel_mut(x, y).copy_from_slice(&px[..c]);
        }
    }
    Ok(out)
}

fn scale(image: &Image, factor: f64) -> Result<Image> {
    let (w, h, c) = (image.width(), image.height(), image.channels());
    if factor < 1.0 {
        return shrink(image, factor);
    }
    // Keep the output pixels whose centre maps inside [0, w - 1]: (i + 0.5) / f - 0.5 >= 0.
    let first = |len: usize| ((factor / 2.0 - 0.5).ceil().max(0.0) as usize, len);
    let span = |len: usize| {
        let (start, _) = first(len);
        let last = ((len as f64 - 0.5) * factor - 0.5).floor() as usize;
        (start, last + 1 - start)
    };
    let ((x0, ow), (y0, oh)) = (span(w), span(h));
    let mut out = Image::new(ow, oh, c)?;
    let mut px = [0.0f32; 4];
    for y in 0..oh {
        let sy = ((y0 + y) as f64 + 0.5) / factor - 0.5;
        for x in 0..ow {
            let sx = ((x0 + x) as f64 + 0.5) / factor - 0.5;
            sample_bicubic(image, sx as f32, sy as f32, Edge::Clamp, &mut px);
            out.pixel_mut(x, y).copy_from_slice(&px[..c]);
        }
    }
    Ok(out)
}

/// Area averaging (see [`shrink_area`]) by `factor` < 1.
fn shrink(image: &Image, factor: f64) -> Result<Image> {
    let (w, h) = (image.width(), image.height());
    shrink_area(
        image,
        ((w as f64 * factor).round() as usize).max(1),
        ((h as f64 * factor).round() as usize).max(1),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::testing::noise;

    #[test]
    fn mirror_and_flip_twice_are_the_identity() {
        let img = noise(13, 9, 3, 1);
        for d in [Deformation::Mirror, Deformation::Flip] {
            let once = d.apply(&img).unwrap();
            assert_ne!(once, img);
            assert_eq!(d.apply(&once).unwrap(), img);
        }
        assert_eq!(
            Deformation::Mirror.apply(&img).unwrap().pixel(0, 2),
            img.pixel(12, 2)
        );
    }

    #[test]
    fn a_quarter_turn_is_a_transpose_then_a_flip() {
        let img = noise(13, 9, 3, 2);
        let turned = Deformation::Rotate { degrees: 90.0 }.apply(&img).unwrap();
        let expected = Deformation::Flip.apply(&transpose(&img)).unwrap();
        assert_eq!(turned, expected);
        // Counter-clockwise: the right column becomes the top row.
        assert_eq!(turned.pixel(0, 0), img.pixel(12, 0));
        let full = deform(&img, &[Deformation::Rotate { degrees: 90.0 }; 4]).unwrap();
        assert_eq!(full, img);
        assert_eq!(
            Deformation::Rotate { degrees: -90.0 }.apply(&img).unwrap(),
            Deformation::Rotate { degrees: 270.0 }.apply(&img).unwrap()
        );
        assert_eq!(
            Deformation::Rotate { degrees: 180.0 }.apply(&img).unwrap(),
            deform(&img, &[Deformation::Mirror, Deformation::Flip]).unwrap()
        );
    }

    #[test]
    fn a_cyclic_shift_moves_pixels_and_undoes_itself() {
        let img = noise(10, 7, 2, 3);
        let moved = Deformation::Shift { dx: 3, dy: -2 }.apply(&img).unwrap();
        assert_eq!(moved.pixel(3, 0), img.pixel(0, 2));
        assert_eq!(
            Deformation::Shift { dx: -3, dy: 2 }.apply(&moved).unwrap(),
            img
        );
    }

    #[test]
    fn any_angle_keeps_only_pixels_from_inside_the_sample() {
        // A constant sample framed by a one-pixel border of another colour: if any output pixel
        // read the border (or beyond), it would not be the constant.
        let img = Image::from_fn(40, 30, 1, |x, y, _| {
            if x == 0 || y == 0 || x == 39 || y == 29 {
                1.0
            } else {
                0.25
            }
        })
        .unwrap();
        for degrees in [1.0, 17.0, 30.0, 45.0, 60.0, 89.0, 135.0, -20.0] {
            let out = Deformation::Rotate { degrees }.apply(&img).unwrap();
            assert!(
                out.data().iter().all(|&v| (v - 0.25).abs() < 1e-6),
                "{degrees}"
            );
            let (iw, ih) = inscribed_size(37.0, 27.0, f64::to_radians(degrees));
            assert_eq!(
                (out.width(), out.height()),
                (iw as usize, ih as usize),
                "{degrees}"
            );
        }
    }

    #[test]
    fn the_inscribed_rectangle_is_the_largest_that_fits() {
        // A square turned by 45 degrees holds a square of side s / sqrt(2).
        let (w, h) = inscribed_size(100.0, 100.0, std::f64::consts::FRAC_PI_4);
        assert!((w - 100.0 / 2f64.sqrt()).abs() < 1e-9 && (w - h).abs() < 1e-9);
        // A brute-force check on a long rectangle: no larger centred rectangle of the same
        // aspect fits, and the found one's corners lie inside.
        let (a, b, angle) = (120.0, 40.0, 0.3f64);
        let (rw, rh) = inscribed_size(a, b, angle);
        let inside = |w: f64, h: f64| {
            [(1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)]
                .iter()
                .all(|(sx, sy)| {
                    let (x, y) = (sx * w / 2.0, sy * h / 2.0);
                    let (u, v) = (
                        x * angle.cos() + y * angle.sin(),
                        -x * angle.sin() + y * angle.cos(),
                    );
                    u.abs() <= a / 2.0 + 1e-9 && v.abs() <= b / 2.0 + 1e-9
                })
        };
        assert!(inside(rw, rh));
        let area = rw * rh;
        for i in 1..200 {
            let aspect = f64::from(i) / 20.0;
            // Largest centred rectangle of this aspect that fits, by bisection.
            let (mut lo, mut hi) = (0.0, 200.0);
            for _ in 0..60 {
                let mid = (lo + hi) / 2.0;
                if inside(mid * aspect, mid) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            assert!(lo * aspect * lo <= area + 1e-6, "aspect {aspect}");
        }
    }

    #[test]
    fn scaling_keeps_the_mean_and_reads_only_the_sample() {
        let img = noise(32, 24, 3, 4);
        let mean =
            |i: &Image| i.data().iter().map(|&v| f64::from(v)).sum::<f64>() / i.data().len() as f64;
        let half = Deformation::Scale { factor: 0.5 }.apply(&img).unwrap();
        assert_eq!((half.width(), half.height()), (16, 12));
        assert!((mean(&half) - mean(&img)).abs() < 1e-5);
        // An exact halving averages 2x2 blocks.
        let expected: f32 = [(0, 0), (1, 0), (0, 1), (1, 1)]
            .iter()
            .map(|&(x, y)| img.pixel(x, y)[1])
            .sum::<f32>()
            / 4.0;
        assert!((half.pixel(0, 0)[1] - expected).abs() < 1e-6);
        let double = Deformation::Scale { factor: 2.0 }.apply(&img).unwrap();
        // Centres (i + 0.5) / 2 - 0.5 inside [0, 31]: i = 1..=62.
        assert_eq!((double.width(), double.height()), (62, 46));
        // Pixel 1 of the doubled image maps to source 0.25: between pixels 0 and 1.
        let (lo, hi) = (
            img.pixel(0, 0)[0].min(img.pixel(1, 0)[0]),
            img.pixel(0, 0)[0].max(img.pixel(1, 0)[0]),
        );
        let v = double.pixel(0, 0)[0];
        assert!(v >= lo - 1e-6 && v <= hi + 1e-6);
    }

    #[test]
    fn bad_deformations_are_named_errors() {
        let img = noise(16, 16, 3, 5);
        let msg = |d: Deformation| d.apply(&img).unwrap_err().to_string();
        assert!(msg(Deformation::Scale { factor: 9.0 }).contains("scale"));
        assert!(msg(Deformation::Scale { factor: f64::NAN }).contains("scale"));
        assert!(
            msg(Deformation::Rotate {
                degrees: f64::INFINITY
            })
            .contains("rotation")
        );
        let tiny = noise(9, 9, 1, 6);
        let err = Deformation::Rotate { degrees: 45.0 }
            .apply(&tiny)
            .unwrap_err()
            .to_string();
        assert!(err.contains("rotate 45"), "{err}");
    }

    #[test]
    fn ranges_expand_to_one_texture_per_value() {
        let ranges = DeformationRanges {
            rotation: Some(Steps {
                from: 0.0,
                to: 90.0,
                step: 30.0,
            }),
            scale: Some(Steps {
                from: 0.5,
                to: 1.5,
                step: 0.5,
            }),
            shift: Some(Steps {
                from: 0.0,
                to: 0.5,
                step: 0.25,
            }),
            mirror: true,
            flip: false,
        };
        let list = ranges.expand(64, 32).unwrap();
        let labels: Vec<String> = list.iter().map(Deformation::label).collect();
        assert_eq!(
            labels,
            [
                "rotate 30°",
                "rotate 60°",
                "rotate 90°",
                "scale 0.5x",
                "scale 1.5x",
                "shift 16,8",
                "shift 32,16",
                "mirror"
            ]
        );
        let too_many = DeformationRanges {
            rotation: Some(Steps {
                from: 0.0,
                to: 360.0,
                step: 1.0,
            }),
            ..DeformationRanges::default()
        };
        assert!(
            too_many
                .expand(64, 64)
                .unwrap_err()
                .to_string()
                .contains("at most")
        );
        let backwards = DeformationRanges {
            scale: Some(Steps {
                from: 2.0,
                to: 1.0,
                step: 0.5,
            }),
            ..DeformationRanges::default()
        };
        assert!(
            backwards
                .expand(64, 64)
                .unwrap_err()
                .to_string()
                .contains("scale")
        );
    }
}
