//! Exemplar pixels the matches may not use, per level: a neighbourhood is excluded when it holds
//! any excluded pixel. Inpainting excludes the hole of an image that is its own exemplar, whose
//! pixels are unknown (see `crate::methods::inpainting`).

use crate::core::pyramid::half_size;
use crate::solvers::box_sum::box_sums;

/// `mask` (`width` x `height`, true = excluded) one octave down: a coarse pixel is excluded when
/// any fine pixel its blur reads is (the binomial kernel reaches two pixels, so a coarse pixel
/// at x reads fine pixels 2x - 2 ..= 2x + 2).
#[must_use]
pub fn halve(mask: &[bool], width: usize, height: usize) -> Vec<bool> {
    let (hw, hh) = (half_size(width), half_size(height));
    let mut out = vec![false; hw * hh];
    for (i, out) in out.iter_mut().enumerate() {
        let (x, y) = (i % hw, i / hw);
        let (x0, x1) = ((2 * x).saturating_sub(2), (2 * x + 2).min(width - 1));
        let (y0, y1) = ((2 * y).saturating_sub(2), (2 * y + 2).min(height - 1));
        *out = (y0..=y1).any(|fy| mask[fy * width + x0..=fy * width + x1].contains(&true));
    }
    out
}

/// The exclusion table of the `size` x `size` neighbourhoods at `octave` of an exemplar of
/// `width` x `height` whose excluded pixels at full resolution are `mask`: per top-left corner
/// (`width - size + 1` per row at that octave), 1 where the neighbourhood holds an excluded
/// pixel, else 0.
#[must_use]
pub fn exclusion_table(
    mask: &[bool],
    (width, height): (usize, usize),
    octave: usize,
    size: usize,
) -> Vec<f32> {
    let (mut mask, mut w, mut h) = (mask.to_vec(), width, height);
    for _ in 0..octave {
        mask = halve(&mask, w, h);
        (w, h) = (half_size(w), half_size(h));
    }
    let values: Vec<f32> = mask.iter().map(|&m| f32::from(u8::from(m))).collect();
    let sums = box_sums(&values, w, h, size, false);
    let (nx, ny) = (w - size + 1, h - size + 1);
    let mut table = Vec::with_capacity(nx * ny);
    for y in 0..ny {
        table.extend(sums[y * w..y * w + nx].iter().map(|&s| f32::from(u8::from(s > 0.5))));
    }
    table
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_neighbourhood_is_excluded_exactly_when_it_holds_an_excluded_pixel() {
        // Against a direct scan, on a 13x9 mask with two excluded pixels.
        let (w, h, size) = (13usize, 9usize, 4usize);
        let mut mask = vec![false; w * h];
        mask[3 * w + 5] = true;
        mask[8 * w + 12] = true;
        let table = exclusion_table(&mask, (w, h), 0, size);
        let nx = w - size + 1;
        assert_eq!(table.len(), nx * (h - size + 1));
        for (i, &t) in table.iter().enumerate() {
            let (x, y) = (i % nx, i / nx);
            let holds = (y..y + size).any(|yy| (x..x + size).any(|xx| mask[yy * w + xx]));
            assert_eq!(t == 1.0, holds, "({x}, {y})");
        }
    }

    #[test]
    fn halving_keeps_every_pixel_the_blur_reads() {
        let (w, h) = (10usize, 6usize);
        let mut mask = vec![false; w * h];
        mask[2 * w + 7] = true;
        let half = halve(&mask, w, h);
        assert_eq!(half.len(), 5 * 3);
        // Coarse x reads fine 2x - 2 ..= 2x + 2: fine x = 7 for x = 3 and 4, fine y = 2 for y = 0 to 2.
        let excluded: Vec<(usize, usize)> = (0..half.len())
            .filter(|&i| half[i])
            .map(|i| (i % 5, i / 5))
            .collect();
        assert_eq!(excluded, vec![(3, 0), (4, 0), (3, 1), (4, 1), (3, 2), (4, 2)]);
    }
}
