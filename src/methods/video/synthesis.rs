//! The state every video mode shares: the source volumes, the output canvas with its seam memory,
//! and the seam cost between neighbouring voxels. Seam finding (`seam.rs`) extends it; the
//! session (`session.rs`: the loop's two placements, 7.D's fixed frames) and the offset choice
//! (`placement.rs`) drive it.

use super::canvas::{Canvas, Patch, UNCOVERED};
use super::source::{Axis, Source};
use crate::methods::graphcut::anatomy::GraphView;
use crate::methods::graphcut::cost::{Sample, match_cost};

/// One frame of a placement's seam graph.
#[derive(Debug, Clone, PartialEq)]
pub struct GraphSlice {
    /// The canvas frame shown.
    pub t: usize,
    /// The patch's box in the output: its first frame and frame count.
    pub first_frame: usize,
    pub frames: usize,
    pub view: GraphView,
}

/// Sources and canvas of one video synthesis.
pub struct Synthesis {
    pub sources: Vec<Source>,
    pub canvas: Canvas,
    /// Use M' (eq. 5, divided by the gradients along the edge) instead of M (eq. 1).
    pub gradient_cost: bool,
    /// Whether placements keep a frame of their graph for the page's placement anatomy, and the
    /// last one kept.
    pub record_anatomy: bool,
    pub last_graph: Option<GraphSlice>,
    /// The max-flow graph, reset at every placement so its buffers keep their memory (as in
    /// graph-cut textures).
    pub graph: crate::solvers::maxflow::Graph,
}

impl Synthesis {
    #[must_use]
    pub fn new(sources: Vec<Source>, canvas: Canvas, gradient_cost: bool) -> Synthesis {
        Synthesis {
            sources,
            canvas,
            gradient_cost,
            record_anatomy: false,
            last_graph: None,
            graph: crate::solvers::maxflow::Graph::default(),
        }
    }

    /// The source voxel patch `patch` copies to output voxel `i`, if it reaches it.
    #[inline]
    #[must_use]
    pub fn source_voxel(&self, patch: Patch, i: usize) -> Option<usize> {
        let (x, y, t) = self.canvas.coords(i);
        let v = &self.sources[patch.source as usize].volume;
        let sx = x as i64 - i64::from(patch.tx);
        let sy = y as i64 - i64::from(patch.ty);
        let st = t as i64 - i64::from(patch.tt);
        ((0..v.width() as i64).contains(&sx)
            && (0..v.height() as i64).contains(&sy)
            && (0..v.frames() as i64).contains(&st))
        .then(|| v.index(sx as usize, sy as usize, st as usize))
    }

    /// What `patch` shows at output voxel `i`, with its gradient along `axis`.
    #[inline]
    #[must_use]
    pub fn sample(&self, patch: Patch, i: usize, axis: Axis) -> Option<Sample<'_>> {
        let k = self.source_voxel(patch, i)?;
        let source = &self.sources[patch.source as usize];
        Some(Sample {
            colour: source.volume.voxel(k),
            gradient: source.gradient[axis as usize][k],
        })
    }

    /// M(s, t, A, B) (or M') for neighbouring voxels s, t (t after s along `axis`) when s shows
    /// patch `a` and t shows `b`: the image version's cost (`graphcut::cost`), unchanged; only
    /// the edge now also runs along time. Zero when a == b.
    #[must_use]
    pub fn seam_cost(&self, s: usize, t: usize, axis: Axis, a: Patch, b: Patch) -> f32 {
        if a == b {
            return 0.0;
        }
        match_cost(
            self.sample(a, s, axis),
            self.sample(b, s, axis),
            self.sample(a, t, axis),
            self.sample(b, t, axis),
            self.gradient_cost,
        )
    }

    /// The patch of a covered voxel.
    #[inline]
    #[must_use]
    pub fn patch_of(&self, i: usize) -> Option<Patch> {
        let label = self.canvas.label[i];
        (label != UNCOVERED).then(|| self.canvas.patches[label as usize])
    }

    /// The output voxels `patch` covers, in source scan order.
    #[must_use]
    pub fn footprint(&self, patch: Patch) -> Vec<usize> {
        let (w, h, _) = self.canvas.size();
        let [xs, ys, ts] = self.footprint_box(patch);
        let mut out = Vec::with_capacity(xs.len() * ys.len() * ts.len());
        for t in ts {
            for y in ys.clone() {
                let row = (t * h + y) * w;
                out.extend(xs.clone().map(|x| row + x));
            }
        }
        out
    }

    /// The x, y and t ranges of the output the patch covers (the box [`Synthesis::footprint`]
    /// lists in t, y, x order).
    #[must_use]
    pub fn footprint_box(&self, patch: Patch) -> [std::ops::Range<usize>; 3] {
        let v = &self.sources[patch.source as usize].volume;
        let (w, h, d) = self.canvas.size();
        let range = |offset: i32, len: usize, size: usize| {
            let first = i64::from(offset).max(0);
            let last = (i64::from(offset) + len as i64).min(size as i64);
            first as usize..last.max(first) as usize
        };
        [
            range(patch.tx, v.width(), w),
            range(patch.ty, v.height(), h),
            range(patch.tt, v.frames(), d),
        ]
    }
}
