//! Feature maps (Wu & Yu 2004, section 2.3): curvilinear edges and ridges as one-pixel-wide
//! curves (a mask), with the smoothed tangent angle and the detector's response at every pixel
//! and the threshold used; a pixel's orientation bucket comes from its angle ([`bucket`]).
//!
//! Bilateral filter (sigma_d = 2, sigma_r = 10/256) on the grey image; edge response = gradient
//! magnitude by central differences, ridge response = |Laplacian|; a two-pass classification
//! (strong: at least the global high threshold, a percentile of the responses; weak: within 2
//! pixels of a strong pixel of response R and at least alpha R, or chained from such a pixel
//! along its curve's tangent at the same threshold); then thinning, weakest first.
//! The tangent is the direction across the dominant gradient of the structure tensor smoothed over
//! 5x5, so a ridge's centre, where the gradient vanishes, still gets its line's direction.

use super::bilateral::bilateral;
use super::thinning::thin;
use crate::core::{Error, Image, Result};

/// Which curves make the map.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FeatureKind {
    /// Boundaries between regions (stone outlines, plank edges).
    Edges,
    /// Thin lines, dark or bright (mortar, grout, cracks).
    Ridges,
    /// Both, thinned together.
    Both,
}

/// Options of the detector.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DetectOptions {
    /// Default: ridges (the thin lines of tiles, bricks and planks give one curve, where edges
    /// give two, one either side).
    pub kind: FeatureKind,
    /// The global high threshold as a fraction of the responses below it. Default: 0.9 (the
    /// strongest 10% are strong features).
    pub percentile: f32,
    /// Weak features: at least alpha times a nearby strong response. Default: 0.3 (the paper's).
    pub alpha: f32,
}

impl Default for DetectOptions {
    fn default() -> Self {
        DetectOptions {
            kind: FeatureKind::Ridges,
            percentile: 0.9,
            alpha: 0.3,
        }
    }
}

impl DetectOptions {
    /// Checks the options: the percentile (JS `threshold`) in 0.5..0.999, alpha in 0..1.
    pub fn validate(&self) -> Result<()> {
        if !self.percentile.is_finite() || !(0.5..=0.999).contains(&self.percentile) {
            return Err(Error::InvalidParameter {
                name: "threshold",
                reason: format!(
                    "must be a percentile between 0.5 and 0.999, got {}",
                    self.percentile
                ),
            });
        }
        if !self.alpha.is_finite() || !(0.0..=1.0).contains(&self.alpha) {
            return Err(Error::InvalidParameter {
                name: "alpha",
                reason: format!("must be between 0 and 1, got {}", self.alpha),
            });
        }
        Ok(())
    }
}

/// Number of orientation buckets (section 2.1).
pub const BUCKETS: usize = 4;

/// A feature map: the curves and, at every pixel, the tangent angle in 0..pi (so that a pixel
/// painted on by hand gets the orientation of the image there; its bucket is [`bucket`] of it)
/// and the detector's response.
#[derive(Debug, Clone, PartialEq)]
pub struct FeatureMap {
    /// Width in pixels, the image's.
    pub width: usize,
    /// Height in pixels, the image's.
    pub height: usize,
    /// True on a curve pixel: one value per pixel, row by row.
    pub mask: Vec<bool>,
    /// The smoothed tangent angle at every pixel, in radians, 0..pi.
    pub angle: Vec<f32>,
    /// The detector's response at every pixel: gradient magnitude (edges), |Laplacian|
    /// (ridges) or the larger of the two (both).
    pub response: Vec<f32>,
    /// The absolute high threshold used (to detect on other images the same way).
    pub threshold: f32,
}

/// The bucket of a tangent angle in 0..pi: four intervals of pi/4, the first centred on the
/// horizontal.
#[must_use]
pub fn bucket(angle: f32) -> usize {
    let a = (angle + std::f32::consts::FRAC_PI_8).rem_euclid(std::f32::consts::PI);
    ((a / std::f32::consts::FRAC_PI_4) as usize).min(BUCKETS - 1)
}

/// The unsigned difference of two tangents as unit vectors, |v1 - v2| with the sign of v2
/// chosen to make it smallest (a tangent has no direction).
#[must_use]
pub fn tangent_difference(a: f32, b: f32) -> f32 {
    let d = (a - b).abs().rem_euclid(std::f32::consts::PI);
    let d = d.min(std::f32::consts::PI - d);
    2.0 * crate::core::math::sinf(d / 2.0)
}

fn grey(image: &Image) -> Vec<f32> {
    let c = image.channels();
    image
        .data()
        .chunks_exact(c)
        .map(|p| match c {
            1 | 2 => p[0],
            _ => 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2],
        })
        .collect()
}

/// Responses and tangent angles of an image.
fn responses(image: &Image, kind: FeatureKind) -> (Vec<f32>, Vec<f32>) {
    let (w, h) = (image.width(), image.height());
    let g = bilateral(&grey(image), w, h, 2.0, 10.0 / 256.0);
    // Mirrored borders: a clamped border would read a ramp's last step as a ridge.
    let reflect = |i: isize, n: usize| {
        let n = n as isize;
        let r = if i < 0 {
            -i
        } else if i >= n {
            2 * n - 2 - i
        } else {
            i
        };
        r.clamp(0, n - 1) as usize
    };
    let at = |x: isize, y: isize| g[reflect(y, h) * w + reflect(x, w)];
    let mut gx = vec![0.0f32; w * h];
    let mut gy = vec![0.0f32; w * h];
    let mut response = vec![0.0f32; w * h];
    for y in 0..h as isize {
        for x in 0..w as isize {
            let i = y as usize * w + x as usize;
            gx[i] = 0.5 * (at(x + 1, y) - at(x - 1, y));
            gy[i] = 0.5 * (at(x, y + 1) - at(x, y - 1));
            let edge = crate::core::math::hypotf(gx[i], gy[i]);
            let ridge =
                (at(x + 1, y) + at(x - 1, y) + at(x, y + 1) + at(x, y - 1) - 4.0 * at(x, y)).abs();
            response[i] = match kind {
                FeatureKind::Edges => edge,
                FeatureKind::Ridges => ridge,
                FeatureKind::Both => edge.max(ridge),
            };
        }
    }
    // Structure tensor over 5x5, then the tangent across the dominant gradient.
    let mut angle = vec![0.0f32; w * h];
    for y in 0..h as isize {
        for x in 0..w as isize {
            let (mut jxx, mut jxy, mut jyy) = (0.0f32, 0.0f32, 0.0f32);
            for dy in -2..=2 {
                for dx in -2..=2 {
                    let (xx, yy) = (
                        (x + dx).clamp(0, w as isize - 1),
                        (y + dy).clamp(0, h as isize - 1),
                    );
                    let j = yy as usize * w + xx as usize;
                    jxx += gx[j] * gx[j];
                    jxy += gx[j] * gy[j];
                    jyy += gy[j] * gy[j];
                }
            }
            let gradient = 0.5 * crate::core::math::atan2f(2.0 * jxy, jxx - jyy);
            angle[y as usize * w + x as usize] =
                (gradient + std::f32::consts::FRAC_PI_2).rem_euclid(std::f32::consts::PI);
        }
    }
    (response, angle)
}

/// Detects the feature map of `image`.
pub fn detect(image: &Image, options: DetectOptions) -> Result<FeatureMap> {
    options.validate()?;
    let (response, angle) = responses(image, options.kind);
    // The response at the percentile's rank: a selection, not a sort (the same value; sorting
    // 12 million responses of a photo takes 6 s natively).
    let mut ranked = response.clone();
    let index = ((ranked.len() - 1) as f32 * options.percentile).round() as usize;
    let (_, at_rank, _) = ranked.select_nth_unstable_by(index, f32::total_cmp);
    // Never below a floor: a flat image has no features, not noise promoted to features.
    let threshold = at_rank.max(1e-3);
    Ok(classify(
        image.width(),
        image.height(),
        response,
        angle,
        threshold,
        options.alpha,
    ))
}

/// Detects with a given absolute high threshold (the exemplar's), so that an output is judged by
/// the exemplar's standard.
pub fn detect_with_threshold(
    image: &Image,
    kind: FeatureKind,
    threshold: f32,
    alpha: f32,
) -> FeatureMap {
    let (response, angle) = responses(image, kind);
    classify(
        image.width(),
        image.height(),
        response,
        angle,
        threshold,
        alpha,
    )
}

fn classify(
    w: usize,
    h: usize,
    response: Vec<f32>,
    angle: Vec<f32>,
    threshold: f32,
    alpha: f32,
) -> FeatureMap {
    let strong: Vec<bool> = response.iter().map(|&r| r >= threshold).collect();
    let mut mask = strong.clone();
    // Second pass: weaker responses near a strong one, against a threshold set by it; each weak
    // pixel taken carries that threshold on along its curve (see `chain`).
    let mut low = vec![f32::INFINITY; w * h];
    let mut chain_ends = Vec::new();
    for y in 0..h {
        for x in 0..w {
            let i = y * w + x;
            if !strong[i] {
                continue;
            }
            let bound = alpha * response[i];
            for yy in y.saturating_sub(2)..(y + 3).min(h) {
                for xx in x.saturating_sub(2)..(x + 3).min(w) {
                    let j = yy * w + xx;
                    if !strong[j] && response[j] >= bound && bound < low[j] {
                        if low[j] == f32::INFINITY {
                            chain_ends.push(j);
                        }
                        low[j] = bound;
                        mask[j] = true;
                    }
                }
            }
        }
    }
    chain(&mut mask, &mut low, chain_ends, (&response, &angle), w, h);
    thin(&mut mask, &response, w, h);
    FeatureMap {
        width: w,
        height: h,
        mask,
        angle,
        response,
        threshold,
    }
}

/// Chaining along curves: from each weak pixel the second pass took, the neighbours that
/// continue its curve (within [`CHAIN_CONE`] of its tangent, either way) join when their
/// response reaches the threshold the pixel carries, and carry it on in turn. A broken strong
/// curve is followed through its weak stretch to the next strong piece, while weak responses
/// across the curve (texture beside it) are not taken. Pixels are visited first in, first out,
/// from the ends in scan order, so the map does not depend on anything but the image.
fn chain(
    mask: &mut [bool],
    low: &mut [f32],
    ends: Vec<usize>,
    (response, angle): (&[f32], &[f32]),
    w: usize,
    h: usize,
) {
    let mut queue = std::collections::VecDeque::from(ends);
    while let Some(i) = queue.pop_front() {
        let (x, y) = ((i % w) as isize, (i / w) as isize);
        let (tx, ty) = (
            crate::core::math::cosf(angle[i]),
            crate::core::math::sinf(angle[i]),
        );
        for (dx, dy) in NEIGHBOURS {
            let (nx, ny) = (x + dx, y + dy);
            if nx < 0 || ny < 0 || nx >= w as isize || ny >= h as isize {
                continue;
            }
            let along = (tx * dx as f32 + ty * dy as f32).abs() / crate::core::math::hypotf(dx as f32, dy as f32);
            let j = ny as usize * w + nx as usize;
            if along < CHAIN_CONE || mask[j] || response[j] < low[i] {
                continue;
            }
            mask[j] = true;
            low[j] = low[i];
            queue.push_back(j);
        }
    }
}

/// A neighbour continues a pixel's curve when the cosine between the step to it and the
/// pixel's tangent is at least this (within about 35 degrees).
const CHAIN_CONE: f32 = 0.82;

/// The eight neighbours of a pixel.
const NEIGHBOURS: [(isize, isize); 8] = [
    (-1, -1),
    (0, -1),
    (1, -1),
    (-1, 0),
    (1, 0),
    (-1, 1),
    (0, 1),
    (1, 1),
];

impl FeatureMap {
    /// Feature pixels.
    #[must_use]
    pub fn count(&self) -> usize {
        self.mask.iter().filter(|&&m| m).count()
    }

    /// Paints (true) or erases (false) a disc of `radius` at (x, y), as the paper allows the
    /// designer to correct the map.
    pub fn paint(&mut self, x: f32, y: f32, radius: f32, on: bool) {
        let r = radius.max(0.5);
        for yy in (y - r).floor().max(0.0) as usize..((y + r).ceil() as usize + 1).min(self.height)
        {
            for xx in
                (x - r).floor().max(0.0) as usize..((x + r).ceil() as usize + 1).min(self.width)
            {
                if crate::core::math::hypotf(xx as f32 - x, yy as f32 - y) <= r {
                    self.mask[yy * self.width + xx] = on;
                }
            }
        }
    }

    /// Paints (true) or erases (false) the stroke from (x0, y0) to (x1, y1) with discs of
    /// `radius`, at most half a pixel apart, so that a brush moved fast over a large map leaves a
    /// curve without gaps (a pointer reports its moves tens of map pixels apart on a photo).
    /// The part of the stroke outside the map (grown by the brush) is left out, so a stroke
    /// reaching far off the map paints what lies on it, in time bounded by the map's size
    /// (clipped in f64: exact to a small fraction of a pixel for ends within 1e9 pixels).
    pub fn paint_line(
        &mut self,
        (x0, y0): (f32, f32),
        (x1, y1): (f32, f32),
        radius: f32,
        on: bool,
    ) {
        let margin = f64::from(radius.max(0.5)) + 1.0;
        let (a, b) = (
            (f64::from(x0), f64::from(y0)),
            (f64::from(x1), f64::from(y1)),
        );
        let Some((t0, t1)) = clip_segment(
            a,
            b,
            (-margin, self.width as f64 + margin),
            (-margin, self.height as f64 + margin),
        ) else {
            return;
        };
        let at = |t: f64| {
            (
                (a.0 + t * (b.0 - a.0)) as f32,
                (a.1 + t * (b.1 - a.1)) as f32,
            )
        };
        let ((x0, y0), (x1, y1)) = (at(t0), at(t1));
        let length = crate::core::math::hypotf(x1 - x0, y1 - y0);
        let steps = (2.0 * length).ceil().max(1.0) as usize;
        for k in 0..=steps {
            let t = k as f32 / steps as f32;
            self.paint(x0 + t * (x1 - x0), y0 + t * (y1 - y0), radius, on);
        }
    }
}

/// The parameter range [t0, t1] of the segment from `a` to `b` that lies in the box `xs` x `ys`
/// (Liang-Barsky), or None when it misses the box.
fn clip_segment(
    a: (f64, f64),
    b: (f64, f64),
    xs: (f64, f64),
    ys: (f64, f64),
) -> Option<(f64, f64)> {
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, d, lo, hi) in [(a.0, b.0 - a.0, xs.0, xs.1), (a.1, b.1 - a.1, ys.0, ys.1)] {
        if d == 0.0 {
            if p < lo || p > hi {
                return None;
            }
            continue;
        }
        let (mut ta, mut tb) = ((lo - p) / d, (hi - p) / d);
        if ta > tb {
            std::mem::swap(&mut ta, &mut tb);
        }
        t0 = t0.max(ta);
        t1 = t1.min(tb);
    }
    (t0 <= t1).then_some((t0, t1))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::testing::sample;
    use crate::methods::features::thinning::components;

    #[test]
    fn a_painted_stroke_is_one_curve_without_gaps() {
        let image = Image::from_fn(64, 32, 1, |_, _, _| 0.5).unwrap();
        let mut map = detect(&image, DetectOptions::default()).unwrap();
        assert_eq!(map.count(), 0, "a flat image has no features");
        // A diagonal stroke 40 pixels long in one move, as a fast pointer reports it.
        map.paint_line((4.0, 4.0), (44.0, 24.0), 0.6, true);
        assert_eq!(components(&map.mask, 64, 32), 1, "one connected curve");
        for x in 4usize..=44 {
            let y: usize = 4 + (x - 4) / 2;
            let near = (y.saturating_sub(1)..=y + 1).any(|yy| map.mask[yy * 64 + x]);
            assert!(near, "the curve passes x = {x}");
        }
        // Erasing the middle with a wider brush cuts it in two.
        map.paint_line((24.0, 0.0), (24.0, 31.0), 2.5, false);
        assert_eq!(components(&map.mask, 64, 32), 2);
        assert!(!map.mask[14 * 64 + 24]);
        // A stroke from far off the map paints the part on it, at once.
        let before = map.count();
        map.paint_line((-1e8, 10.0), (1e8, 10.0), 0.5, true);
        assert!(
            (0..64).all(|x| map.mask[10 * 64 + x]),
            "row 10 painted across"
        );
        assert!(map.count() > before);
        map.paint_line((-1e8, -1e8), (-1e7, 1e8), 0.5, true); // misses the map
        map.paint_line((70.0, 5.0), (90.0, 5.0), 0.5, true);
    }

    #[test]
    fn buckets_and_tangent_differences() {
        use std::f32::consts::{FRAC_PI_2, FRAC_PI_4, PI};
        assert_eq!(bucket(0.0), 0);
        assert_eq!(bucket(PI - 0.01), 0);
        assert_eq!(bucket(FRAC_PI_4), 1);
        assert_eq!(bucket(FRAC_PI_2), 2);
        assert_eq!(bucket(3.0 * FRAC_PI_4), 3);
        assert!(
            tangent_difference(0.1, PI - 0.1) < 0.21,
            "nearly the same line"
        );
        assert!((tangent_difference(0.0, FRAC_PI_2) - 2f32.sqrt()).abs() < 1e-5);
    }

    #[test]
    fn a_drawn_grid_gives_thin_lines_with_their_orientations() {
        // Dark grout lines every 16 pixels on a light field, with some noise.
        let img = Image::from_fn(64, 64, 1, |x, y, _| {
            let line = x % 16 == 8 || y % 16 == 8;
            (if line { 0.2 } else { 0.8 }) + 0.01 * (((x * 31 + y * 17) % 7) as f32)
        })
        .unwrap();
        let map = detect(&img, DetectOptions::default()).unwrap();
        // Every grout pixel away from the crossings is found, one pixel wide.
        for x in (0..64).filter(|x| (x % 16) > 10 || (x % 16) < 6) {
            assert!(map.mask[8 * 64 + x], "horizontal line at x = {x}");
            assert!(!map.mask[7 * 64 + x] && !map.mask[9 * 64 + x]);
            assert_eq!(bucket(map.angle[8 * 64 + x]), 0, "horizontal tangent");
            assert_eq!(bucket(map.angle[x * 64 + 8]), 2, "vertical tangent");
        }
        assert_eq!(components(&map.mask, 64, 64), 1, "one connected grid");
    }

    /// A dark line, strong at both ends and faint for 16 pixels between them, and a faint line
    /// of its own 8 pixels below: the second pass follows the first line through its faint
    /// stretch (chaining along its tangent), and takes nothing of the second, which no strong
    /// pixel reaches.
    #[test]
    fn the_second_pass_chains_a_broken_line_through_its_faint_stretch() {
        let img = Image::from_fn(64, 40, 1, |x, y, _| {
            let faint = (20..36).contains(&x);
            match y {
                16 if faint => 0.6,
                16 => 0.3,
                24 => 0.6,
                _ => 0.8,
            }
        })
        .unwrap();
        let (response, angle) = responses(&img, FeatureKind::Ridges);
        let (strong, faint) = (response[16 * 64 + 10], response[16 * 64 + 28]);
        assert!(faint > 0.3 * strong && faint < 0.5 * strong, "{strong} {faint}");
        let map = classify(64, 40, response, angle, 0.75 * strong, 0.3);
        let on = |x: usize, y: usize| (y - 1..=y + 1).any(|yy| map.mask[yy * 64 + x]);
        // Where the line's darkness steps (x = 19 to 20, 35 to 36) the Laplacian along it is
        // small; everywhere else the line is found, its faint middle (23 to 32) by chaining.
        for x in (2..62).filter(|x| ![19, 20, 35, 36].contains(x)) {
            assert!(on(x, 16), "the broken line at x = {x}");
            assert!(!on(x, 24), "the faint line alone at x = {x}");
        }
    }

    #[test]
    fn real_textures_have_features_and_flat_ones_do_not() {
        let tiles = detect(&sample("tiles_64"), DetectOptions::default()).unwrap();
        assert!(tiles.count() > 100, "{}", tiles.count());
        let flat = Image::from_fn(32, 32, 3, |_, _, _| 0.5).unwrap();
        assert_eq!(detect(&flat, DetectOptions::default()).unwrap().count(), 0);
        let bad = DetectOptions {
            percentile: 2.0,
            ..DetectOptions::default()
        };
        assert!(
            detect(&flat, bad)
                .unwrap_err()
                .to_string()
                .contains("threshold")
        );
    }
}
