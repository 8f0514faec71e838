//! The bilateral filter (Tomasi & Manduchi 1998) that Wu & Yu 2004 (section 2.3) run before
//! edge and ridge detection: it smooths texture noise but keeps edges sharp. Closeness
//! sigma_d = 2 pixels, similarity sigma_r = 10/256 of the grey range.

/// Filters a `width` x `height` grey image (values in 0..1). The window reaches 2 sigma_d; the
/// spatial weights are tabulated once, the range weights computed per pair.
#[must_use]
pub fn bilateral(
    grey: &[f32],
    width: usize,
    height: usize,
    sigma_d: f32,
    sigma_r: f32,
) -> Vec<f32> {
    let radius = (2.0 * sigma_d).ceil() as isize;
    let side = (2 * radius + 1) as usize;
    let mut spatial = vec![0.0f32; side * side];
    for dy in -radius..=radius {
        for dx in -radius..=radius {
            let d2 = (dx * dx + dy * dy) as f32;
            spatial[((dy + radius) as usize) * side + (dx + radius) as usize] =
                crate::core::math::expf(-d2 / (2.0 * sigma_d * sigma_d));
        }
    }
    let range_scale = -1.0 / (2.0 * sigma_r * sigma_r);
    let mut out = vec![0.0f32; grey.len()];
    for y in 0..height as isize {
        for x in 0..width as isize {
            let centre = grey[(y as usize) * width + x as usize];
            let (mut sum, mut norm) = (0.0f32, 0.0f32);
            for dy in -radius..=radius {
                let yy = y + dy;
                if yy < 0 || yy >= height as isize {
                    continue;
                }
                let row = &spatial[((dy + radius) as usize) * side..];
                for dx in -radius..=radius {
                    let xx = x + dx;
                    if xx < 0 || xx >= width as isize {
                        continue;
                    }
                    let v = grey[(yy as usize) * width + xx as usize];
                    let d = v - centre;
                    let w =
                        row[(dx + radius) as usize] * crate::core::math::expf(d * d * range_scale);
                    sum += w * v;
                    norm += w;
                }
            }
            out[(y as usize) * width + x as usize] = sum / norm;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Rng;

    /// The filter written straight from its definition, in f64, over the whole image.
    fn direct(grey: &[f32], w: usize, h: usize, sd: f64, sr: f64) -> Vec<f64> {
        let r = (2.0 * sd).ceil() as i64;
        (0..w * h)
            .map(|i| {
                let (x, y) = ((i % w) as i64, (i / w) as i64);
                let c = f64::from(grey[i]);
                let (mut s, mut n) = (0.0, 0.0);
                for yy in 0..h as i64 {
                    for xx in 0..w as i64 {
                        if (xx - x).abs() > r || (yy - y).abs() > r {
                            continue;
                        }
                        let v = f64::from(grey[(yy as usize) * w + xx as usize]);
                        let d2 = ((xx - x).pow(2) + (yy - y).pow(2)) as f64;
                        let wgt = crate::core::math::exp(-d2 / (2.0 * sd * sd))
                            * crate::core::math::exp(-(v - c).powi(2) / (2.0 * sr * sr));
                        s += wgt * v;
                        n += wgt;
                    }
                }
                s / n
            })
            .collect()
    }

    #[test]
    fn it_matches_the_direct_definition_and_keeps_a_step_edge() {
        let (w, h) = (17, 13);
        let mut rng = Rng::new(5);
        let grey: Vec<f32> = (0..w * h)
            .map(|i| if i % w < 8 { 0.2 } else { 0.8 } + 0.02 * rng.next_f32())
            .collect();
        let fast = bilateral(&grey, w, h, 2.0, 10.0 / 256.0);
        let slow = direct(&grey, w, h, 2.0, 10.0 / 256.0);
        for (a, b) in fast.iter().zip(&slow) {
            assert!((f64::from(*a) - b).abs() < 1e-5, "{a} vs {b}");
        }
        // The step survives: the columns either side of it stay 0.6 apart.
        assert!(fast[6 * w + 8] - fast[6 * w + 7] > 0.55);
    }
}
