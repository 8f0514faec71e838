//! The anatomy of one placement, for teaching: the cost surface C(t) of eq. 2 / eq. 4
//! over every candidate offset with the probability eq. 3 gives each, and the graph of section 3
//! whose minimum cut is the seam, laid out per pixel of the patch's box. Recorded only when asked
//! ([`super::Session::set_anatomy`]): a synthesis that nobody watches pays nothing.

use super::region::Candidate;
use super::seam_graph::SeamGraph;
use crate::solvers::maxflow::HARD_CONSTRAINT;

/// C(t) and exp(-C / (k sigma^2)) over the rectangle of offsets that holds every candidate.
#[derive(Debug, Clone, PartialEq)]
pub struct CostSurface {
    /// The offset of the grid's first cell (output coordinates of a patch's top-left corner;
    /// negative where patches start left of or above the output).
    pub x: i64,
    pub y: i64,
    pub width: usize,
    pub height: usize,
    /// Area-normalised SSD per offset, the lowest over the sources when rotated or mirrored
    /// copies share an offset; infinite where no unused candidate is.
    pub cost: Vec<f32>,
    /// The probability eq. 3 gives each offset (summed over sources), summing to 1.
    pub probability: Vec<f32>,
    /// Grid cell of the offset the placement drew.
    pub chosen: Option<(usize, usize)>,
    /// k sigma^2, the denominator of eq. 3.
    pub temperature: f64,
}

/// Where a candidate's offset goes on the surface. `wrap` is the output size when it wraps:
/// offsets were reduced modulo it, so each is put back next to the region (`anchor`, the
/// region's top-left corner).
#[derive(Clone, Copy)]
struct Placing {
    anchor: (i64, i64),
    wrap: Option<(usize, usize)>,
}

impl Placing {
    fn at(self, tx: i32, ty: i32) -> (i64, i64) {
        let unwrap = |t: i32, a: i64, len: Option<usize>| -> i64 {
            let t = i64::from(t);
            match len {
                // The candidate's unreduced offset is the one at most one output size before the
                // region's corner.
                Some(n) => a - (a - t).rem_euclid(n as i64),
                None => t,
            }
        };
        (
            unwrap(tx, self.anchor.0, self.wrap.map(|w| w.0)),
            unwrap(ty, self.anchor.1, self.wrap.map(|w| w.1)),
        )
    }
}

impl CostSurface {
    /// The surface of `scored` (candidates with their costs), with `chosen` marked. `wrap` is
    /// the output size when it wraps: offsets were reduced modulo it, so each is put back next
    /// to the region (`anchor`, the region's top-left corner).
    #[must_use]
    ///
    /// `drawn`: the candidates eq. 3 actually drew from, with the costs it drew by, when they
    /// are not `scored` (feature-guided placement draws among the best by colour, by colour
    /// plus feature cost); the probabilities are then theirs, and 0 elsewhere.
    pub fn new(
        scored: &[Candidate],
        drawn: Option<&[Candidate]>,
        chosen: Option<(i32, i32)>,
        temperature: f64,
        anchor: (i64, i64),
        wrap: Option<(usize, usize)>,
    ) -> Option<CostSurface> {
        let offsets = |c: &[Candidate]| -> Vec<((i32, i32), f32)> {
            c.iter()
                .map(|c| ((c.patch.tx, c.patch.ty), c.cost))
                .collect()
        };
        let drawn = drawn.map(offsets);
        let place = Placing { anchor, wrap };
        CostSurface::placed(
            &offsets(scored),
            drawn.as_deref(),
            chosen,
            temperature,
            place,
        )
    }

    /// The same from plain (offset, cost) pairs: for placements whose candidates are not image
    /// patches (a slice of video's spatio-temporal offsets, [`crate::methods::video::anatomy`]).
    #[must_use]
    pub fn from_offsets(
        scored: &[((i32, i32), f32)],
        chosen: Option<(i32, i32)>,
        temperature: f64,
        anchor: (i64, i64),
        wrap: Option<(usize, usize)>,
    ) -> Option<CostSurface> {
        let place = Placing { anchor, wrap };
        CostSurface::placed(scored, None, chosen, temperature, place)
    }

    fn placed(
        scored: &[((i32, i32), f32)],
        drawn: Option<&[((i32, i32), f32)]>,
        chosen: Option<(i32, i32)>,
        temperature: f64,
        placing: Placing,
    ) -> Option<CostSurface> {
        let place = |tx: i32, ty: i32| placing.at(tx, ty);
        let points: Vec<(i64, i64)> = scored.iter().map(|&((tx, ty), _)| place(tx, ty)).collect();
        let x0 = points.iter().map(|p| p.0).min()?;
        let y0 = points.iter().map(|p| p.1).min()?;
        let width = (points.iter().map(|p| p.0).max()? - x0 + 1) as usize;
        let height = (points.iter().map(|p| p.1).max()? - y0 + 1) as usize;
        let mut cost = vec![f32::INFINITY; width * height];
        let mut probability = vec![0.0f32; width * height];
        for (&(_, c), &(x, y)) in scored.iter().zip(&points) {
            let k = (y - y0) as usize * width + (x - x0) as usize;
            cost[k] = cost[k].min(c);
        }
        let pool = drawn.unwrap_or(scored);
        let best = pool.iter().map(|c| c.1).fold(f32::INFINITY, f32::min);
        // As `choose` draws: relative to the best cost, uniform when no cost is finite.
        let weight = |c: f32| -> f64 {
            if !best.is_finite() {
                1.0
            } else if c.is_finite() {
                crate::core::math::exp(-(f64::from(c) - f64::from(best)) / temperature)
            } else {
                0.0
            }
        };
        let total: f64 = pool.iter().map(|c| weight(c.1)).sum();
        for &((tx, ty), c) in pool {
            let (x, y) = place(tx, ty);
            let k = (y - y0) as usize * width + (x - x0) as usize;
            probability[k] += (weight(c) / total.max(f64::MIN_POSITIVE)) as f32;
        }
        let chosen = chosen.map(|(tx, ty)| {
            let (x, y) = place(tx, ty);
            ((x - x0) as usize, (y - y0) as usize)
        });
        Some(CostSurface {
            x: x0,
            y: y0,
            width,
            height,
            cost,
            probability,
            chosen,
            temperature,
        })
    }
}

/// What a pixel of the patch's box is in the graph.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(u8)]
pub enum NodeKind {
    /// Outside the patch, or a pixel the patch does not cover.
    Outside = 0,
    /// Uncovered: it takes the new patch B whatever the cut, so it has no node.
    New = 1,
    /// A covered pixel whose side the cut decides.
    Free = 2,
    /// Constrained to keep the old output A (the patch's border next to covered pixels).
    KeepOld = 3,
    /// Constrained to take the new patch B (the centre of a covered error region).
    TakeNew = 4,
}

/// The seam graph of one placement per pixel of the patch's `width` x `height` box (row-major,
/// box coordinates; the box's top-left corner is the patch's offset).
#[derive(Debug, Clone, PartialEq)]
pub struct GraphView {
    pub x: i64,
    pub y: i64,
    pub width: usize,
    pub height: usize,
    /// [`NodeKind`] of each pixel, as its `u8`.
    pub kind: Vec<u8>,
    /// Capacity of the arc from each pixel to its right (`right`) and lower (`down`) neighbour:
    /// M(s, t, A, B); where an old seam lies between them, the cheaper of the two arcs through
    /// its seam node. NaN: no arc (a neighbour outside the box or uncovered: the arc to an
    /// uncovered pixel becomes a terminal arc to B, which the kinds show as `New`).
    pub right: Vec<f32>,
    pub down: Vec<f32>,
    /// The remembered cost of the old seam between each pixel and its right / lower neighbour
    /// (the seam node's arc to B, section 3.1); NaN where no old seam runs.
    pub old_right: Vec<f32>,
    pub old_down: Vec<f32>,
    /// 1 where the pixel took the new patch after the cut.
    pub taken: Vec<u8>,
}

impl GraphView {
    /// The view of `graph` for a patch whose box starts at `origin` and is `size` pixels;
    /// `local` maps an output pixel to its index in the box, `next(i, axis)` is the output's
    /// neighbour function, `taken` the pixels that took the patch.
    #[must_use]
    pub fn new(
        graph: &SeamGraph,
        origin: (i64, i64),
        (width, height): (usize, usize),
        local: &dyn Fn(usize) -> Option<usize>,
        next: &dyn Fn(usize, usize) -> Option<usize>,
        taken: &[usize],
    ) -> GraphView {
        // Dynamic closures: one copy of this teaching-only code serves images and video (the
        // .wasm size budget), at no cost that matters for a view built once per placement.
        let n = width * height;
        let mut view = GraphView {
            x: origin.0,
            y: origin.1,
            width,
            height,
            kind: vec![NodeKind::Outside as u8; n],
            right: vec![f32::NAN; n],
            down: vec![f32::NAN; n],
            old_right: vec![f32::NAN; n],
            old_down: vec![f32::NAN; n],
            taken: vec![0; n],
        };
        for &i in &graph.uncovered {
            if let Some(k) = local(i) {
                view.kind[k] = NodeKind::New as u8;
            }
        }
        for &i in &graph.cells {
            if let Some(k) = local(i) {
                view.kind[k] = NodeKind::Free as u8;
            }
        }
        let cells = graph.cells.len() as u32;
        // The arc from pixel s to its neighbour t, written on s under the axis that joins them.
        let set = |view: &mut GraphView, s: usize, t: usize, value: f32, old: bool| {
            let Some(k) = local(s) else { return };
            let (arcs, olds) = if next(s, 0) == Some(t) {
                (&mut view.right, &mut view.old_right)
            } else if next(s, 1) == Some(t) {
                (&mut view.down, &mut view.old_down)
            } else {
                return;
            };
            let slot = if old { &mut olds[k] } else { &mut arcs[k] };
            *slot = if slot.is_nan() {
                value
            } else {
                slot.min(value)
            };
        };
        // A seam node's arcs: to its cells s and t; the cheaper of the two is where cutting
        // through it makes a new seam.
        let mut through = vec![f32::NAN; graph.seams.len()];
        for &(a, b, c) in &graph.edges {
            match (a < cells, b < cells) {
                (true, true) => set(
                    &mut view,
                    graph.cells[a as usize],
                    graph.cells[b as usize],
                    c,
                    false,
                ),
                (true, false) | (false, true) => {
                    let slot = &mut through[(a.max(b) - cells) as usize];
                    *slot = if slot.is_nan() { c } else { slot.min(c) };
                }
                (false, false) => {}
            }
        }
        for &(node, to_a, to_b) in &graph.terminals {
            if node >= cells {
                let k = (node - cells) as usize;
                let (s, t) = graph.seams[k];
                set(&mut view, s, t, through[k], false);
                set(&mut view, s, t, to_b, true);
                continue;
            }
            let Some(k) = local(graph.cells[node as usize]) else {
                continue;
            };
            if to_a >= HARD_CONSTRAINT {
                view.kind[k] = NodeKind::KeepOld as u8;
            } else if to_b >= HARD_CONSTRAINT && view.kind[k] != NodeKind::KeepOld as u8 {
                view.kind[k] = NodeKind::TakeNew as u8;
            }
        }
        for &i in taken {
            if let Some(k) = local(i) {
                view.taken[k] = 1;
            }
        }
        view
    }
}

#[cfg(test)]
mod tests {
    use super::super::canvas::UNCOVERED;
    use super::super::options::{Options, Placement};
    use super::super::session::Session;
    use super::*;
    use crate::core::testing::sample;

    /// Steps `session` until its output is partly covered, then records one placement and
    /// returns the canvas as it was before it (pixels, labels).
    fn record_one(session: &mut Session, before: usize) -> (Vec<f32>, Vec<u32>) {
        for _ in 0..before {
            session.step().expect("step");
        }
        let canvas = &session.synthesis().canvas;
        let state = (canvas.pixels.data().to_vec(), canvas.label.clone());
        session.set_anatomy(true);
        session.step().expect("step");
        state
    }

    /// The cost surface equals a direct SSD over the covered pixels under each offset's patch,
    /// normalised by that area (eq. 2), computed from the canvas as it was before the placement.
    #[test]
    fn the_cost_surface_is_the_direct_area_normalised_ssd() {
        let exemplar = sample("gravel_64");
        let options = Options {
            output_width: 96,
            output_height: 80,
            placement: Placement::EntirePatch,
            ..Options::default()
        };
        let mut session = Session::new(&exemplar, options).expect("session");
        let (pixels, label) = record_one(&mut session, 3);
        let surface = session.placement_costs().expect("recorded").clone();
        let (w, h, c) = (96i64, 80i64, exemplar.channels());
        let (ex, ey) = (exemplar.width() as i64, exemplar.height() as i64);
        let mut checked = 0;
        for gy in (0..surface.height).step_by(3) {
            for gx in (0..surface.width).step_by(3) {
                let cost = surface.cost[gy * surface.width + gx];
                if !cost.is_finite() {
                    continue;
                }
                let (tx, ty) = (surface.x + gx as i64, surface.y + gy as i64);
                let (mut ssd, mut area) = (0.0f64, 0.0f64);
                for v in 0..ey {
                    for u in 0..ex {
                        let (x, y) = (tx + u, ty + v);
                        if !(0..w).contains(&x) || !(0..h).contains(&y) {
                            continue;
                        }
                        let i = (y * w + x) as usize;
                        if label[i] == UNCOVERED {
                            continue;
                        }
                        area += 1.0;
                        let o = &pixels[i * c..(i + 1) * c];
                        let e = exemplar.pixel(u as usize, v as usize);
                        ssd += o
                            .iter()
                            .zip(e)
                            .map(|(a, b)| f64::from(a - b).powi(2))
                            .sum::<f64>();
                    }
                }
                let direct = (ssd / area) as f32;
                assert!(
                    (cost - direct).abs() <= 1e-3 * direct.max(1e-2),
                    "offset ({tx}, {ty}): surface {cost}, direct {direct}"
                );
                checked += 1;
            }
        }
        assert!(checked > 20, "only {checked} offsets checked");
        let total: f32 = surface.probability.iter().sum();
        assert!((total - 1.0).abs() < 1e-3, "probabilities sum to {total}");
        let (cx, cy) = surface.chosen.expect("a patch was placed");
        assert!(surface.cost[cy * surface.width + cx].is_finite());
    }

    /// The graph view agrees with what the placement did: the pixels it marks as taken show the
    /// new patch, uncovered ones were all taken, and pixels held to the old output were not.
    #[test]
    fn the_graph_view_matches_the_placement() {
        let exemplar = sample("gravel_64");
        let options = Options {
            output_width: 96,
            output_height: 96,
            refinement_patches: 2,
            ..Options::default()
        };
        let mut session = Session::new(&exemplar, options).expect("session");
        for before in [3, 40] {
            record_one(&mut session, before);
            let view = session.placement_graph().expect("recorded").clone();
            let s = session.synthesis();
            let index = s.canvas.patches.len() as u32 - 1;
            let (mut free, mut taken_free, mut kept) = (0, 0, 0);
            for v in 0..view.height {
                for u in 0..view.width {
                    let k = v * view.width + u;
                    let (x, y) = (view.x + u as i64, view.y + v as i64);
                    if !(0..96).contains(&x) || !(0..96).contains(&y) {
                        assert_eq!(view.kind[k], NodeKind::Outside as u8);
                        continue;
                    }
                    let shows_new = s.canvas.label[(y * 96 + x) as usize] == index;
                    assert_eq!(view.taken[k] == 1, shows_new, "pixel ({x}, {y})");
                    match view.kind[k] {
                        k if k == NodeKind::New as u8 => assert!(shows_new),
                        k if k == NodeKind::KeepOld as u8 => {
                            assert!(!shows_new);
                            kept += 1;
                        }
                        k if k == NodeKind::Free as u8 => {
                            free += 1;
                            taken_free += usize::from(shows_new);
                        }
                        _ => {}
                    }
                }
            }
            assert!(free > 0 && kept > 0, "free {free}, kept {kept}");
            assert!(taken_free < free, "the cut kept some covered pixels");
            let arcs = view
                .right
                .iter()
                .chain(&view.down)
                .filter(|c| c.is_finite());
            assert!(arcs.clone().count() > 0 && arcs.clone().all(|&c| c >= 0.0));
        }
        assert!(
            session
                .placement_graph()
                .unwrap()
                .old_right
                .iter()
                .any(|c| c.is_finite())
                || session
                    .placement_graph()
                    .unwrap()
                    .old_down
                    .iter()
                    .any(|c| c.is_finite()),
            "a placement over a covered output meets old seams"
        );
    }

    #[test]
    fn nothing_is_recorded_unless_asked() {
        let mut session = Session::new(&sample("gravel_64"), Options::default()).expect("session");
        session.step().expect("step");
        session.step().expect("step");
        assert!(session.placement_costs().is_none() && session.placement_graph().is_none());
        session.set_anatomy(true);
        session.step().expect("step");
        assert!(session.placement_costs().is_some() && session.placement_graph().is_some());
        session.set_anatomy(false);
        assert!(session.placement_costs().is_none() && session.placement_graph().is_none());
    }
}
