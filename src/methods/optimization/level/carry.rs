//! Carrying matches into a grid: from the previous level's (between levels, node centres
//! scaled) or from this grid's own moved along a flow (between animation frames), with the
//! fractions of a pixel kept when matches are sub-pixel (see [`super::phases`]).

use super::{LevelSolver, phases};
use crate::methods::optimization::schedule::nearest_corner;
use crate::solvers::nn::{Neighbourhoods, Pos};

/// A grid and its matches, where carried matches come from.
struct OldGrid<'a> {
    cols: &'a [usize],
    rows: &'a [usize],
    matches: &'a [Pos],
    size: usize,
    /// The space the matches index (its copies are phases when stacked).
    space: &'a Neighbourhoods,
    /// Where each node's content lies relative to its match beyond the phase (empty: nowhere).
    offsets: &'a [(f64, f64)],
}

impl LevelSolver {
    /// Replaces every node's match from another solver's: the node's centre is mapped by
    /// `to_old` into `old`'s output coordinates, the old node nearest to it is followed to its
    /// match, moved by the offset from that node's centre, and scaled by `scale` into this
    /// level's exemplar (the ratio of exemplar sizes). Used between levels (centres scale).
    pub fn carry_from(
        &mut self,
        old: &LevelSolver,
        to_old: impl Fn(f64, f64) -> (f64, f64),
        scale: (f64, f64),
    ) {
        let old = OldGrid {
            cols: &old.cols,
            rows: &old.rows,
            matches: &old.matches,
            size: old.setup.size,
            space: old.matcher.space(),
            offsets: &old.offsets,
        };
        let (carried, offsets) = self.carried(&old, to_old, scale);
        self.matches = carried;
        self.offsets = offsets;
        self.refresh_local();
        self.distances.fill(f32::INFINITY);
        self.pixel_distances.fill(f32::INFINITY);
        self.settle();
    }

    /// Moves the matches along a motion: each node takes the match found at `to_old` of its
    /// centre in this same grid (between animation frames: the centre moved back along the flow),
    /// to the nearest half pixel with sub-pixel matches.
    pub fn move_along(&mut self, to_old: impl Fn(f64, f64) -> (f64, f64)) {
        let old = OldGrid {
            cols: &self.cols,
            rows: &self.rows,
            matches: &self.matches,
            size: self.setup.size,
            space: self.matcher.space(),
            offsets: &self.offsets,
        };
        let (carried, offsets) = self.carried(&old, to_old, (1.0, 1.0));
        self.matches = carried;
        self.offsets = offsets;
        self.refresh_local();
        self.distances.fill(f32::INFINITY);
        self.pixel_distances.fill(f32::INFINITY);
        self.settle();
    }

    /// The carried matches and, with sub-pixel matches, where each node's content lies beyond
    /// its match and phase.
    fn carried(
        &self,
        old: &OldGrid<'_>,
        to_old: impl Fn(f64, f64) -> (f64, f64),
        scale: (f64, f64),
    ) -> (Vec<Pos>, Vec<(f64, f64)>) {
        let half_old = old.size as f64 / 2.0;
        let half_new = self.setup.size as f64 / 2.0;
        let old_nx = old.cols.len();
        let space = self.matcher.space();
        let (ex_nx, ex_ny) = space.extent();
        let sub_pixel = self.stacked.is_some();
        let nx = self.cols.len();
        let mut offsets = Vec::with_capacity(if sub_pixel { self.matches.len() } else { 0 });
        let matches = (0..self.matches.len())
            .map(|n| {
                let (x, y) = (self.cols[n % nx], self.rows[n / nx]);
                let (cx, cy) = to_old(x as f64 + half_new, y as f64 + half_new);
                let i = nearest_corner(old.cols, cx - half_old);
                let j = nearest_corner(old.rows, cy - half_old);
                let old_node = j * old_nx + i;
                // The exemplar position of the old match's content: its phase, and what
                // rounding to the phase left over.
                let (copy, z) = old.space.copy_of(old.matches[old_node]);
                let (phase_x, phase_y) = phases::offset(copy);
                let (rest_x, rest_y) = old.offsets.get(old_node).copied().unwrap_or_default();
                let zx = (f64::from(z.x) + phase_x + rest_x + cx - old.cols[i] as f64) * scale.0
                    - half_new;
                let zy = (f64::from(z.y) + phase_y + rest_y + cy - old.rows[j] as f64) * scale.1
                    - half_new;
                if !sub_pixel {
                    return space.clamp(zx.round() as i64, zy.round() as i64);
                }
                let ((wx, sx), (wy, sy)) = (phases::split(zx), phases::split(zy));
                let inside = (0..ex_nx as i64).contains(&wx) && (0..ex_ny as i64).contains(&wy);
                let phase = phases::phase(sx, sy);
                let (px, py) = phases::offset(phase);
                // A position clamped into the exemplar keeps no fraction.
                offsets.push(if inside {
                    (zx - wx as f64 - px, zy - wy as f64 - py)
                } else {
                    (0.0, 0.0)
                });
                let whole = space.clamp(wx, wy);
                space.in_copy(if inside { phase } else { 0 }, whole)
            })
            .collect();
        (matches, offsets)
    }
}
