//! The memory budget of a video synthesis (the shared budget of [`crate::core::budget`], default
//! 1024 MiB, settable with `memory_budget_mib`). A wasm32 instance addresses at most 4 GiB, and
//! browsers often refuse to grow one far, so a video whose working set would not fit is refused
//! up front, with a message naming the sizes and the limit, instead of trapping half-way with
//! "out of memory".
//!
//! The working set is estimated from what the synthesis holds (bytes per voxel, measured from the
//! types it allocates):
//!
//! - the input clip and its gradients along x, y and t: 12 + 12 = [`INPUT_BYTES_PER_VOXEL`];
//! - the output canvas: colours 12, patch label 4, seam costs on three edges 12, the node map
//!   of the graph 4, the fixed-voxel mask 1, the box sums of the error region 8, rounded up to [`OUTPUT_BYTES_PER_VOXEL`];
//! - the max-flow graph of one placement, per voxel under the patch: three 6-connected edges
//!   (16 bytes each, two residual arcs of 12), the node's state and terminal arcs (about 48), and
//!   room for old-seam nodes: [`GRAPH_BYTES_PER_VOXEL`];
//! - the 3-D FFT search of matching placement
//!   ([`crate::solvers::fft_ssd::volume_search_bytes`]).

use crate::core::budget::{MAX_MEMORY_BUDGET_MIB, WorkingSet as Estimate};
use crate::core::{Error, Result};

/// The most a single volume's colours may take whatever the budget: the largest budget
/// accepted ([`MAX_MEMORY_BUDGET_MIB`]). A session's own budget is checked by
/// [`WorkingSet::check`].
pub const MAX_VOLUME_BYTES: usize = MAX_MEMORY_BUDGET_MIB << 20;

pub const INPUT_BYTES_PER_VOXEL: usize = 24;
pub const OUTPUT_BYTES_PER_VOXEL: usize = 48;
pub const GRAPH_BYTES_PER_VOXEL: usize = 256;

/// The largest side or frame count accepted at all (beyond it the product checks overflow long
/// before memory is the question).
pub const MAX_DIMENSION: usize = 1 << 16;

/// Fails on an empty volume, a side above [`MAX_DIMENSION`], or one whose colours alone
/// (12 bytes a voxel) exceed [`MAX_VOLUME_BYTES`].
pub fn check_volume(what: &'static str, width: usize, height: usize, frames: usize) -> Result<()> {
    let fail = |reason: String| {
        Err(Error::InvalidParameter {
            name: what,
            reason: format!("{width}x{height}x{frames} (width x height x frames): {reason}"),
        })
    };
    if width == 0 || height == 0 || frames == 0 {
        return fail("every dimension must be at least 1".into());
    }
    if width.max(height).max(frames) > MAX_DIMENSION {
        return fail(format!("no dimension may exceed {MAX_DIMENSION}"));
    }
    // In u64: 65536 x 65536 overflows a wasm32 usize.
    let bytes = width as u64 * height as u64 * frames as u64 * 12;
    if bytes > MAX_VOLUME_BYTES as u64 {
        return fail(format!(
            "its colours alone take {} MiB, more than the largest memory budget, {} MiB",
            bytes.div_ceil(1 << 20),
            MAX_MEMORY_BUDGET_MIB
        ));
    }
    Ok(())
}

/// What a synthesis will hold, in voxels and bytes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct WorkingSet {
    pub input_voxels: usize,
    pub output_voxels: usize,
    pub patch_voxels: usize,
    pub search_bytes: usize,
}

impl WorkingSet {
    /// The estimate in the shared form, part by part.
    #[must_use]
    pub fn estimate(&self) -> Estimate {
        let b = |voxels: usize, per: usize| voxels as u64 * per as u64;
        Estimate::new()
            .with("input", b(self.input_voxels, INPUT_BYTES_PER_VOXEL))
            .with("output", b(self.output_voxels, OUTPUT_BYTES_PER_VOXEL))
            .with("seam graph", b(self.patch_voxels, GRAPH_BYTES_PER_VOXEL))
            .with("FFT search", self.search_bytes as u64)
    }

    #[must_use]
    pub fn bytes(&self) -> u64 {
        self.estimate().bytes()
    }

    /// Fails, naming every size, the estimate and the limit, when the working set exceeds
    /// `budget_mib`.
    pub fn check(
        &self,
        input: (usize, usize, usize),
        output: (usize, usize, usize),
        budget_mib: usize,
    ) -> Result<()> {
        self.estimate().check(
            &format!(
                "input {}x{}x{} and output {}x{}x{} (width x height x frames)",
                input.0, input.1, input.2, output.0, output.1, output.2
            ),
            "video synthesis",
            budget_mib,
        )
    }
}
