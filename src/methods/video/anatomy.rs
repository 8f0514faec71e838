//! The placement anatomy of video textures, reusing the image version's views
//! ([`crate::methods::graphcut::anatomy`]): the cost surface C(t) with the probabilities of eq. 3,
//! and the graph whose minimum cut is the seam surface.
//!
//! Patches and seams here are 3-D (x, y, t), and a teacher shows a class one picture at a time,
//! so both views are one slice, chosen to show what the placement decided:
//! - the cost surface over the spatial offsets (tx, ty) at the temporal offset the placement
//!   drew: "at this time shift, where in space could the patch go?", with the probabilities of
//!   eq. 3 conditioned on that time shift (they sum to 1 over the slice). With temporal offsets
//!   only (7.B: tx = ty = 0), the one axis is time: the surface is a row over tt;
//! - the seam graph in the frame of the patch's box with the most graph nodes (covered voxels:
//!   the overlap), where most of the seam surface is cut; its arcs along time are not drawn (a
//!   slice shows the spatial arcs), but its kinds (held to A at the box's border, in time too)
//!   and the cut are the 3-D graph's.
//!
//! Recorded only while asked for ([`super::Session::set_anatomy`]).

use super::canvas::Patch;
use super::placement::Scored;
use super::seam::SeamGraph;
use super::source::AXES;
use super::synthesis::{GraphSlice, Synthesis};
use crate::methods::graphcut::anatomy::{CostSurface, GraphView};

/// One slice of a placement's cost surface.
#[derive(Debug, Clone, PartialEq)]
pub struct CostSlice {
    /// The slice's axes: false, (tx, ty) at temporal offset `tt`; true, the temporal offsets
    /// (the surface's x is tt, its one row y = 0).
    pub temporal: bool,
    /// The temporal offset of the slice, in canvas frames.
    pub tt: i32,
    pub surface: CostSurface,
}

/// The slice of `scored` through the drawn offset `chosen` (see the module's notes); None when
/// the offsets were not scored (nothing covered yet: a uniform draw).
#[must_use]
pub fn cost_slice(
    scored: &Scored,
    chosen: Patch,
    spatial: bool,
    temperature: f64,
) -> Option<CostSlice> {
    let costs = scored.costs.as_ref()?;
    let offsets: Vec<((i32, i32), f32)> = scored
        .candidates
        .iter()
        .zip(costs)
        .filter(|(p, _)| !spatial || p.tt == chosen.tt)
        .map(|(p, &c)| {
            let at = if spatial { (p.tx, p.ty) } else { (p.tt, 0) };
            (at, c as f32)
        })
        .collect();
    let at = if spatial {
        (chosen.tx, chosen.ty)
    } else {
        (chosen.tt, 0)
    };
    let surface = CostSurface::from_offsets(&offsets, Some(at), temperature, (0, 0), None)?;
    Some(CostSlice {
        temporal: !spatial,
        tt: chosen.tt,
        surface,
    })
}

impl Synthesis {
    /// The frame of `graph` (the graph of placing `patch`, `taken` the voxels that took it) with
    /// the most graph nodes, as the image version's graph view.
    #[must_use]
    pub fn graph_slice(&self, graph: &SeamGraph, patch: Patch, taken: &[usize]) -> GraphSlice {
        let (w, h, _) = self.canvas.size();
        let [xs, ys, ts] = self.footprint_box(patch);
        let mut nodes = vec![0usize; ts.len()];
        for &i in &graph.cells {
            nodes[i / (w * h) - ts.start] += 1;
        }
        // The earliest of the fullest frames.
        let t = ts.start
            + nodes
                .iter()
                .enumerate()
                .max_by(|a, b| a.1.cmp(b.1).then(b.0.cmp(&a.0)))
                .map_or(0, |(k, _)| k);
        let (bw, bh) = (xs.len(), ys.len());
        let local = |j: usize| -> Option<usize> {
            let (x, y, f) = self.canvas.coords(j);
            (f == t && xs.contains(&x) && ys.contains(&y))
                .then(|| (y - ys.start) * bw + (x - xs.start))
        };
        let view = GraphView::new(
            graph,
            (xs.start as i64, ys.start as i64),
            (bw, bh),
            &local,
            &|i, axis| self.canvas.next(i, AXES[axis]),
            taken,
        );
        GraphSlice {
            t,
            first_frame: ts.start,
            frames: ts.len(),
            view,
        }
    }
}
