//! The working set of a texture optimisation (see [`crate::core::budget`]), counted from what the
//! session allocates. The finest level is the peak: every buffer below scales with its output
//! (`N` pixels, `c` channels, `d` feature values per pixel: `c`, or `3c` when the M-step's distance
//! has a gradient term), and a level's buffers are dropped when the next level is entered.
//!
//! - the output, `4c N`, while the previous level's output is resized into it (`c N` more) and
//!   a full-size copy for reading it back (`4c N`);
//! - histogram matching: three tables of 4,097 counts, nothing per pixel;
//! - the M-step's feature map of the output, `4d N` (its queries are made one node at a time);
//! - the E-step's accumulators, weight and colour, `4(1 + c) N`, and with `mu > 0` the gradient
//!   terms (`8(1 + c) N`) and the Poisson conjugate-gradient solve (about `36 N`);
//! - per node of the grid (spacing `w/4`): the match, distances and objective, 32 bytes;
//! - the exemplar pyramid, its neighbourhood space and, with a wavelet energy, every exemplar
//!   neighbourhood transformed (`count * w^2 * d * 4` bytes, for the largest level);
//! - soft constraints, once set: the target and mask at full size and at the level's size, and
//!   the M-step's constrained queries (values and weight gains, `8d N`).
//!
//! The M-step's and E-step's buffers are not live at once, but the allocator does not always
//! reuse a freed block for a larger one, so both are counted (measured in wasm: see the README's
//! "Memory budget" table).

use super::options::{Energy, Options};
use super::schedule::Level;
use crate::core::budget::{WorkingSet, image_bytes};

/// The working set of a session over an exemplar of `channels` channels with schedule
/// `levels`; `constraints`: soft constraints are set (Algorithm 2).
#[must_use]
pub fn working_set(
    options: &Options,
    levels: &[Level],
    exemplar: (usize, usize, usize),
    constraints: bool,
) -> WorkingSet {
    let (ew, eh, c) = exemplar;
    let (w, h) = (options.output_width, options.output_height);
    let n = w as u64 * h as u64;
    let c64 = c as u64;
    // The M-step's feature maps carry gradients when its own weight is above 0.
    let d = if options.search_mu() > 0.0 {
        3 * c64
    } else {
        c64
    };
    let finest = levels.iter().filter(|l| l.octave == 0);
    let nodes = finest
        .clone()
        .map(|l| (w.div_ceil(l.spacing) + 1) as u64 * (h.div_ceil(l.spacing) + 1) as u64)
        .max()
        .unwrap_or(n);
    let space = levels
        .iter()
        .map(|l| {
            let count =
                (l.exemplar_width - l.size + 1) as u64 * (l.exemplar_height - l.size + 1) as u64;
            if options.energy == Energy::Pixels {
                // The exemplar's feature map, plus a k-means tree's grouped positions.
                image_bytes(l.exemplar_width, l.exemplar_height, d as usize) + count * 16
            } else {
                count * (l.size * l.size) as u64 * d * 4
            }
        })
        .max()
        .unwrap_or(0);
    let mut set = WorkingSet::new()
        .with("output", image_bytes(w, h, c) * 2 + n * c64)
        .with("M-step feature map", n * d * 4)
        .with("E-step accumulators", n * (1 + c64) * 4)
        .with("exemplar pyramid", image_bytes(ew, eh, c) * 2)
        .with("exemplar neighbourhoods", space)
        .with("grid nodes", nodes * 32);
    if options.mu > 0.0 {
        set.add("gradient solve", n * (8 * (1 + c64) + 36));
    }
    if constraints {
        set.add("soft constraints", 2 * n * (c64 + 1) * 4);
        // The M-step's constrained queries, read in place: values and weight gains.
        set.add("M-step constrained queries", 2 * n * d * 4);
    }
    set
}

/// What the session is called in messages.
pub const METHOD: &str = "texture optimisation";

#[cfg(test)]
mod tests {
    use super::super::{Options, Session};
    use crate::core::testing::noise;

    fn options(side: usize, budget: usize) -> Options {
        Options {
            output_width: side,
            output_height: side,
            memory_budget_mib: budget,
            ..Options::default()
        }
    }

    #[test]
    fn estimate_grows_with_the_output_and_huge_outputs_are_refused_by_the_constructor() {
        let exemplar = noise(64, 64, 3, 1);
        let bytes = |side| {
            Session::new(&exemplar, options(side, 3584))
                .unwrap()
                .working_set(false)
                .bytes()
        };
        let (small, large) = (bytes(256), bytes(1024));
        assert!(large > 8 * small, "{small} -> {large}");
        // Accepted: constructing only, nothing of the output's size is allocated yet.
        assert!(Session::new(&exemplar, options(2048, 1024)).is_ok());
        let e = Session::new(&exemplar, options(4096, 256))
            .err()
            .unwrap()
            .to_string();
        assert!(
            e.starts_with("output 4096x4096: texture optimisation needs about")
                && e.contains("(estimate: ")
                && e.contains("memory budget of 256 MiB"),
            "{e}"
        );
        let e = Session::new(&exemplar, options(256, 8))
            .err()
            .unwrap()
            .to_string();
        assert!(e.contains("memoryBudgetMiB"), "{e}");
    }
}
