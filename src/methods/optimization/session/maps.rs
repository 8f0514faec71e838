//! What the output shows of the exemplars: the source-coordinate map of material sets (see
//! `crate::methods::transfer`) and, with several exemplars, which one each pixel comes from.

use super::Session;
use crate::core::{Error, Result};
use crate::methods::optimization::level::LevelSolver;
use crate::methods::optimization::schedule::{Level, nearest_nodes};
use crate::methods::transfer::SourceMap;

impl Session {
    /// The exemplar pixel each output pixel shows (see `crate::methods::transfer`): the pixel
    /// of the match of the node whose neighbourhood centre is nearest (the first such node in
    /// the grid's order among equals), at the offset of the pixel in that neighbourhood. The
    /// output itself averages every neighbourhood over the pixel, so transferring the exemplar
    /// gives an image close to the output, not equal to it. Only at full resolution: before
    /// the finest level is entered it fails.
    pub fn source_map(&self) -> Result<SourceMap> {
        let not_yet = || Error::InvalidParameter {
            name: "transfer",
            reason: "the source map is made at full resolution: step on to the finest level \
                     has run"
                .into(),
        };
        if self.several.is_some() {
            return Err(Error::InvalidParameter {
                name: "transfer",
                reason: "needs a session of one exemplar, whose size the other images have".into(),
            });
        }
        let solver = self.solver.as_ref().ok_or_else(not_yet)?;
        let level = self.levels[self.entered.ok_or_else(not_yet)?];
        if level.octave != 0 || self.output.is_none() {
            return Err(not_yet());
        }
        let e = &self.exemplars[0];
        let (w, h) = (level.output_width, level.output_height);
        let shown = self.shown(solver, level);
        SourceMap::new((w, h), (e.width(), e.height()), shown.into_iter().map(Some))
    }

    /// Which exemplar each output pixel of the current level shows (see
    /// [`Session::with_exemplars`]; all 0 with one exemplar): the exemplar of the match of the
    /// neighbourhood whose centre is nearest. `None` before the first level is entered.
    #[must_use]
    pub fn exemplar_map(&self) -> Option<Vec<u32>> {
        let solver = self.solver.as_ref()?;
        let level = self.levels[self.entered?];
        let shown = self.shown(solver, level);
        Some(match &self.several {
            None => vec![0; shown.len()],
            Some(several) => shown
                .into_iter()
                .map(|(_, y)| several.stack.exemplar_at(y << level.octave) as u32)
                .collect(),
        })
    }

    /// The exemplar pixel (at the level's resolution) each output pixel of `level` shows: the
    /// pixel of the match of the node whose neighbourhood centre is nearest, at the pixel's
    /// offset in that neighbourhood.
    fn shown(&self, solver: &LevelSolver, level: Level) -> Vec<(usize, usize)> {
        let (w, h) = (level.output_width, level.output_height);
        let (cols, rows) = solver.grid();
        let (size, wrap) = (level.size, self.options.tileable);
        let (along_x, along_y) = (
            nearest_nodes(cols, w, size, wrap),
            nearest_nodes(rows, h, size, wrap),
        );
        let matches = solver.matches();
        (0..w * h)
            .map(|i| {
                let ((col, dx), (row, dy)) = (along_x[i % w], along_y[i / w]);
                let m = matches[row * cols.len() + col];
                (m.x as usize + dx, m.y as usize + dy)
            })
            .collect()
    }

}
