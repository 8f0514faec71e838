//! An occurrence penalty for the M-step: exemplar neighbourhoods that the current matches already
//! cover more often than their share cost extra, so the output draws on all of the exemplar.
//!
//! The texture energy of Kwatra et al. 2005 only asks that every output neighbourhood look like
//! *some* exemplar neighbourhood; nothing asks that all of the exemplar appear, and outputs
//! settle on a favourite part of it (grass without its leaves, measured by the completeness
//! metric). Later work on texture optimisation (Kaspar et al. 2015, "Self tuning texture
//! optimization") adds a penalty on over-used exemplar patches for this; this is that idea in
//! its simplest form: with C the number of matched neighbourhoods covering each exemplar pixel,
//! C̄ its mean, U(z) the mean of C over candidate z's window divided by C̄, and d̄ the mean
//! distance of the current matches, a candidate costs `alpha * d̄ * max(0, U(z) - 1)` on top of
//! its distance. C̄ is never taken below what one coherent copy gives, `(w / spacing)^2`: an
//! exemplar larger than the output cannot all appear, and below that floor every structure
//! copied whole counted as over-use (see [`Occurrence::rebuild`]).
//!
//! When the output is much larger than the exemplar, every exemplar neighbourhood repeats many
//! times anyway, and pushing for an even count starts to break coherent runs of matches (blurry
//! patches on 64-pixel exemplars at alpha = 1). So alpha is scaled by
//! `min(1, 4 * exemplar area / output area)`: full strength up to the paper's 1:2 scale (128 ->
//! 256), a quarter at 1:4. Measured on the 64-pixel samples (-> 256): a quarter keeps coherence
//! within -4%..+16% and brings completeness 1.5-5x closer; full strength costs up to 50%
//! coherence on grass_64 and gravel_64.

use crate::solvers::nn::{Penalties, Pos};

/// The share of alpha used for an exemplar of `exemplar_area` pixels and an output of
/// `output_area` (see the module notes).
#[must_use]
pub fn strength(exemplar_area: usize, output_area: usize) -> f32 {
    (4.0 * exemplar_area as f32 / output_area.max(1) as f32).min(1.0)
}

/// The coverage of the exemplar by the current matches, ready to price candidates.
#[derive(Debug, Clone, Default)]
pub struct Occurrence {
    /// Neighbourhoods covering each exemplar pixel, `width * height`.
    coverage: Vec<f64>,
    /// `(width + 1) * (height + 1)`: the matches' windows as a 2-D difference array, then the
    /// summed-area table of the coverage (one buffer, kept between M-steps: at a 3000x3000
    /// exemplar each of these arrays is 72 MB, and allocating and zeroing them at every M-step
    /// would add a sixth to its cost).
    sums: Vec<f64>,
    /// The coverage of the row above, before averaging (`width`).
    column: Vec<f64>,
    /// The penalty of every candidate position, `columns` per row: the search prices a
    /// candidate at every step of every query, so each is one load rather than four lookups in
    /// the summed-area table and the arithmetic after them.
    penalties: Vec<f32>,
    columns: usize,
}

impl Occurrence {
    /// Coverage of a `width` x `height` exemplar by `size`-wide neighbourhoods at `matches`;
    /// `scale` is alpha times the mean distance of the matches.
    #[must_use]
    pub fn new(
        matches: &[Pos],
        grid: (usize, usize),
        width: usize,
        height: usize,
        scale: f32,
    ) -> Self {
        Self::remembering(matches, grid, width, height, scale, None)
    }

    /// Like [`Occurrence::new`], with the coverage averaged with `previous` (the coverage of
    /// the last M-step) when given.
    #[must_use]
    pub fn remembering(
        matches: &[Pos],
        grid: (usize, usize),
        width: usize,
        height: usize,
        scale: f32,
        previous: Option<&[f64]>,
    ) -> Self {
        let mut occurrence = Occurrence::default();
        if let Some(previous) = previous {
            occurrence.coverage.extend_from_slice(previous);
        }
        occurrence.rebuild(matches, grid, (width, height), scale, previous.is_some());
        occurrence
    }

    /// Recomputes the coverage and the penalties for `matches` in this occurrence's buffers;
    /// with `remember`, the new coverage is averaged with the one held (the last M-step's).
    pub fn rebuild(
        &mut self,
        matches: &[Pos],
        (size, spacing): (usize, usize),
        (width, height): (usize, usize),
        scale: f32,
        remember: bool,
    ) {
        debug_assert!(scale >= 0.0);
        let remember = remember && self.coverage.len() == width * height;
        let Occurrence {
            coverage,
            sums,
            column,
            penalties,
            columns,
        } = self;
        // Each match adds 1 over its window: a 2-D difference array, then prefix sums.
        let stride = width + 1;
        sums.clear();
        sums.resize(stride * (height + 1), 0.0);
        for m in matches {
            let (x, y) = (m.x as usize, m.y as usize);
            sums[y * stride + x] += 1.0;
            sums[y * stride + x + size] -= 1.0;
            sums[(y + size) * stride + x] -= 1.0;
            sums[(y + size) * stride + x + size] += 1.0;
        }
        if !remember {
            coverage.clear();
            coverage.resize(width * height, 0.0);
        }
        column.clear();
        column.resize(width, 0.0);
        for y in 0..height {
            let mut run = 0.0;
            for x in 0..width {
                run += sums[y * stride + x];
                let here = run + column[x];
                column[x] = here;
                let c = &mut coverage[y * width + x];
                *c = if remember { 0.5 * (here + *c) } else { here };
            }
        }
        // The summed-area table over the (averaged) coverage, in the same buffer: its first
        // row and column are zero, every other entry is written below.
        sums[..stride].fill(0.0);
        for y in 1..=height {
            sums[y * stride] = 0.0;
        }
        for y in 0..height {
            let mut run = 0.0;
            for x in 0..width {
                run += coverage[y * width + x];
                sums[(y + 1) * stride + x + 1] = sums[y * stride + x + 1] + run;
            }
        }
        let table = &*sums;
        // A window's even share of use: the matches' pixels spread evenly over the exemplar, but
        // never less than one coherent copy of it gives (each of its pixels covered by
        // (size / spacing)^2 neighbourhoods). Without that floor, an exemplar with more pixels
        // than the output has an even share below one copy, and every coherent run of matches
        // (the texture's structures, copied whole) is priced as over-use: a 512x512 exemplar
        // to 256x256 comes out blocky and washed out (flat fraction 0.15, against 0.05 with no
        // penalty).
        let per_pixel = (size as f64 / spacing.max(1) as f64).powi(2);
        let even = ((matches.len() * size * size) as f64 / (width * height) as f64).max(per_pixel)
            * (size * size) as f64;
        let inv_even = if even > 0.0 { 1.0 / even } else { 0.0 };
        // Zero up to an even share of use (the window's sum over the even one), then linear in
        // the excess.
        let rows = (height + 1).saturating_sub(size);
        *columns = (width + 1).saturating_sub(size);
        let columns = *columns;
        penalties.clear();
        penalties.extend((0..columns * rows).map(|i| {
            let (x0, y0) = (i % columns, i / columns);
            let (x1, y1) = (x0 + size, y0 + size);
            let window =
                table[y1 * stride + x1] - table[y0 * stride + x1] - table[y1 * stride + x0]
                    + table[y0 * stride + x0];
            scale * (window * inv_even - 1.0).max(0.0) as f32
        }));
    }

    /// Neighbourhoods covering each exemplar pixel (averaged with the previous coverage when
    /// remembering).
    #[must_use]
    pub fn coverage(&self) -> &[f64] {
        &self.coverage
    }

    /// The penalty of candidate `z` (the top-left corner of a neighbourhood inside the
    /// exemplar): zero up to an even share of use, then linear in the excess.
    #[inline]
    #[must_use]
    pub fn penalty(&self, z: Pos) -> f32 {
        self.penalties().at(z)
    }

    /// Every candidate's penalty, for the search's objective.
    #[must_use]
    pub fn penalties(&self) -> Penalties<'_> {
        Penalties {
            values: &self.penalties,
            columns: self.columns,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn penalties_match_a_direct_count_of_each_window() {
        let matches = [
            Pos::new(0, 0),
            Pos::new(2, 1),
            Pos::new(2, 1),
            Pos::new(5, 4),
        ];
        let (w, h, size) = (9, 8, 3);
        // Nodes `size` apart: one copy covers each pixel once.
        let occ = Occurrence::new(&matches, (size, size), w, h, 1.0);
        for zy in 0..=h - size {
            for zx in 0..=w - size {
                let mut direct = 0usize;
                for y in zy..zy + size {
                    for x in zx..zx + size {
                        direct += matches
                            .iter()
                            .filter(|m| {
                                (m.x as usize..m.x as usize + size).contains(&x)
                                    && (m.y as usize..m.y as usize + size).contains(&y)
                            })
                            .count();
                    }
                }
                // 4 matches of 9 pixels over 72 cover a pixel 0.5 times on average, less than
                // one copy: an even window holds one copy's 9.
                let expected = (direct as f64 / 9.0 - 1.0).max(0.0) as f32;
                let penalty = occ.penalty(Pos::new(zx, zy));
                assert!(
                    (penalty - expected).abs() < 1e-6,
                    "({zx}, {zy}): {penalty} vs {expected}"
                );
            }
        }
    }

    #[test]
    fn over_used_windows_cost_and_unused_ones_do_not() {
        // 40 matches of 16 pixels over 256 pixels, nodes 4 apart: 2.5 per pixel on average,
        // more than one copy's 1, so an even window holds 2.5 * 16 = 40; the used one holds
        // 640, 15 over.
        let matches = vec![Pos::new(0, 0); 40];
        let occ = Occurrence::new(&matches, (4, 4), 16, 16, 2.0);
        assert!((occ.penalty(Pos::new(0, 0)) - 2.0 * 15.0).abs() < 1e-4);
        assert_eq!(occ.penalty(Pos::new(12, 12)), 0.0);
    }

    #[test]
    fn one_coherent_copy_is_never_over_use() {
        // An exemplar much larger than the output: the matches are one region copied whole,
        // nodes 2 apart with windows of 4 (each copied pixel under 4 windows), 0.3 per pixel on
        // average over the exemplar. The copy costs nothing; the same region copied twice does.
        let (w, h, size, spacing) = (40, 40, 4, 2);
        let copy: Vec<Pos> = (0..4)
            .flat_map(|j| (0..4).map(move |i| Pos::new(10 + spacing * i, 12 + spacing * j)))
            .collect();
        let once = Occurrence::new(&copy, (size, spacing), w, h, 1.0);
        assert!(once.penalties.iter().all(|&p| p == 0.0));
        let twice: Vec<Pos> = copy.iter().chain(&copy).copied().collect();
        let again = Occurrence::new(&twice, (size, spacing), w, h, 1.0);
        assert!(again.penalty(Pos::new(13, 15)) > 0.9);
        assert_eq!(again.penalty(Pos::new(30, 30)), 0.0);
    }

    #[test]
    fn rebuilding_in_place_equals_building_anew() {
        let first = [Pos::new(0, 0), Pos::new(3, 2), Pos::new(6, 5)];
        let second = [Pos::new(1, 1), Pos::new(3, 2), Pos::new(2, 6)];
        let (w, h, grid) = (10, 9, (3, 1));
        let mut kept = Occurrence::new(&first, grid, w, h, 0.7);
        let anew = Occurrence::remembering(&second, grid, w, h, 1.3, Some(kept.coverage()));
        kept.rebuild(&second, grid, (w, h), 1.3, true);
        assert_eq!(kept.coverage(), anew.coverage());
        assert_eq!(kept.penalties, anew.penalties);
        // Without remembering, or for an exemplar of another size, nothing old is kept.
        kept.rebuild(&first, grid, (w, h), 0.7, false);
        let fresh = Occurrence::new(&first, grid, w, h, 0.7);
        assert_eq!(
            (kept.coverage(), &kept.penalties),
            (fresh.coverage(), &fresh.penalties)
        );
        let inside = [Pos::new(0, 0), Pos::new(3, 2), Pos::new(4, 5)];
        kept.rebuild(&inside, (2, 1), (6, 7), 0.7, true);
        let small = Occurrence::new(&inside, (2, 1), 6, 7, 0.7);
        assert_eq!(
            (kept.coverage(), &kept.penalties),
            (small.coverage(), &small.penalties)
        );
    }

    #[test]
    fn remembered_coverage_is_the_mean_of_now_and_before() {
        let before = Occurrence::new(&[Pos::new(0, 0); 3], (2, 2), 6, 6, 1.0);
        let now = Occurrence::remembering(
            &[Pos::new(4, 4), Pos::new(0, 0), Pos::new(0, 0)],
            (2, 2),
            6,
            6,
            1.0,
            Some(before.coverage()),
        );
        assert_eq!(now.coverage()[0], 2.5);
        assert_eq!(now.coverage()[4 * 6 + 4], 0.5);
        assert_eq!(now.coverage()[2 * 6 + 2], 0.0);
        // The window used 2.5 times on average (sum 10) is over one copy's share (4); one that
        // neither coverage touches costs nothing, nor does half a copy (sum 2).
        assert!(now.penalty(Pos::new(0, 0)) > 0.0);
        assert_eq!(now.penalty(Pos::new(2, 2)), 0.0);
        assert_eq!(now.penalty(Pos::new(4, 4)), 0.0);
    }
}
