//! Teaching views of a texture-optimisation session: the neighbourhood grid with its matches, and
//! where in the exemplar each output pixel comes from, as a colour-coded offset map.

use super::schedule::{Level, nearest_corner};
use super::session::Session;
use crate::core::{Image, Result};
use crate::solvers::nn::Pos;

/// The neighbourhood grid X† of the level last iterated, with its matches z_p and that level's
/// sizes. The step that finishes a level already moves the session on to the next one
/// (`Session::current_level`), but the next level's grid is only built by the step after: until
/// then the grid and matches are the finished level's, and only its sizes place them.
#[derive(Debug, Clone, Copy)]
pub struct Field<'a> {
    pub level: Level,
    /// Top-left corners of the grid's columns and rows, in level pixels.
    pub columns: &'a [usize],
    pub rows: &'a [usize],
    /// z_p of every node (top-left exemplar corner), row by row.
    pub matches: &'a [Pos],
}

/// The grid and matches of `session`, with their level; `None` before the first step.
#[must_use]
pub fn field(session: &Session) -> Option<Field<'_>> {
    let (columns, rows, matches) = session.matches()?;
    // The level whose solver holds these matches (after the step that finishes a level, still
    // that level until the next step enters the next one).
    let level = session.schedule()[session.solver_level()?];
    Some(Field {
        level,
        columns,
        rows,
        matches,
    })
}

/// An RGB image of the output size in which each pixel's colour encodes the exemplar position its
/// neighbourhood was matched to: red grows with exemplar x, green with exemplar y, blue is fixed
/// at one half, so coherent copied regions show as smooth gradients and seams between them as
/// colour jumps. Each pixel takes the match of the grid neighbourhood whose centre is
/// nearest.
pub fn offset_map(session: &Session) -> Result<Image> {
    let opts = session.options();
    let (w, h) = (opts.output_width, opts.output_height);
    let mut map = Image::new(w, h, 3)?;
    let Some(Field {
        level,
        columns: cols,
        rows,
        matches,
    }) = field(session)
    else {
        return Ok(map);
    };
    let half = level.size as f64 / 2.0;
    let column_of: Vec<(usize, f64)> = (0..w)
        .map(|x| {
            nearest(
                cols,
                (x as f64 + 0.5) * level.output_width as f64 / w as f64 - half,
            )
        })
        .collect();
    let (ew, eh) = (level.exemplar_width as f64, level.exemplar_height as f64);
    for y in 0..h {
        let (j, ry) = nearest(
            rows,
            (y as f64 + 0.5) * level.output_height as f64 / h as f64 - half,
        );
        for (x, &(i, rx)) in column_of.iter().enumerate() {
            let z = matches[j * cols.len() + i];
            let u = ((f64::from(z.x) + rx + half) / ew).clamp(0.0, 1.0) as f32;
            let v = ((f64::from(z.y) + ry + half) / eh).clamp(0.0, 1.0) as f32;
            map.pixel_mut(x, y).copy_from_slice(&[u, v, 0.5]);
        }
    }
    Ok(map)
}

/// The corner nearest to `target` and the offset of `target` from it.
fn nearest(corners: &[usize], target: f64) -> (usize, f64) {
    let i = nearest_corner(corners, target);
    (i, target - corners[i] as f64)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::testing::sample;
    use crate::methods::optimization::{EventKind, Options};

    /// Checks the offset map against the grid and matches the session holds: at the output pixel
    /// over each node's centre, the map shows that node's match. The level the matches belong to
    /// is the one the solver was built for, found in the schedule by its sizes.
    fn assert_map_shows_the_matches(session: &Session, map: &Image, step: usize) {
        let (cols, rows, matches) = session.matches().expect("stepped");
        let setup = session.level_solver().expect("stepped").setup();
        let level = session
            .schedule()
            .iter()
            .find(|l| {
                (l.output_width, l.output_height, l.size)
                    == (setup.output_width, setup.output_height, setup.size)
            })
            .expect("the solver's level is planned");
        let (w, h) = (map.width(), map.height());
        let (sx, sy) = (
            w as f64 / level.output_width as f64,
            h as f64 / level.output_height as f64,
        );
        let half = level.size as f64 / 2.0;
        // The pixel over a node's centre lies within half an output pixel (1/2s level pixels) of
        // it, so its exemplar position may be off by that much.
        let tolerance = [
            0.5 / sx / level.exemplar_width as f64 + 1e-4,
            0.5 / sy / level.exemplar_height as f64 + 1e-4,
        ];
        for (j, &row) in rows.iter().enumerate() {
            for (i, &col) in cols.iter().enumerate() {
                let (x, y) = (
                    ((col as f64 + half) * sx) as usize,
                    ((row as f64 + half) * sy) as usize,
                );
                let z = matches[j * cols.len() + i];
                let expected = [
                    ((f64::from(z.x) + half) / level.exemplar_width as f64).clamp(0.0, 1.0),
                    ((f64::from(z.y) + half) / level.exemplar_height as f64).clamp(0.0, 1.0),
                ];
                let shown = map.pixel(x.min(w - 1), y.min(h - 1));
                for (axis, (&got, want)) in shown.iter().zip(expected).enumerate() {
                    assert!(
                        (f64::from(got) - want).abs() <= tolerance[axis],
                        "step {step}, node ({i}, {j}) at pixel ({x}, {y}), axis {axis}: \
                         map {got}, match {want} (level {}x{}, size {})",
                        level.output_width,
                        level.output_height,
                        level.size
                    );
                }
            }
        }
    }

    #[test]
    fn the_offset_map_pairs_each_grid_with_its_own_level_even_on_the_step_ending_it() {
        let exemplar = sample("gravel_64");
        let options = Options {
            output_width: 64,
            output_height: 48,
            iterations: 2,
            ..Options::default()
        };
        let mut session = Session::new(&exemplar, options).unwrap();
        for step in 1.. {
            let event = session.step().unwrap();
            let setup = session.level_solver().unwrap().setup();
            let level = field(&session).unwrap().level;
            assert_eq!(
                (level.output_width, level.output_height, level.size),
                (setup.output_width, setup.output_height, setup.size),
                "step {step}: the field's level is the solver's"
            );
            let map = offset_map(&session).unwrap();
            assert_map_shows_the_matches(&session, &map, step);
            if event.kind == EventKind::Done {
                break;
            }
        }
    }
}
