//! The M-step: for every output neighbourhood x_p, the nearest exemplar neighbourhood z_p, by the
//! chosen search. Every search starts from the current match and only accepts a closer one, so
//! the quadratic energy never rises in an M-step whichever search is used.

use crate::core::Rng;
use crate::solvers::nn::kmeans_tree::KMeansTree;
use crate::solvers::nn::patchmatch::{self, QueryGrid};
use crate::solvers::nn::{
    Neighbourhoods, Objective, Pos, Progress, Queries, Search, exact,
};

/// PatchMatch sweeps per M-step (forward, backward, forward). The EM loop calls it again every
/// iteration, warm-started. Measured on the samples (128 -> 256, `cargo run --release --example
/// bench`): 2 sweeps end 2% above the exact search's energy on gravel_128, 3 sweeps end below it
/// for 10-40% more time, 4 sweeps gain nothing more.
pub const PATCHMATCH_PASSES: usize = 3;

/// The exemplar's neighbourhoods at one level, with the search structure built over them.
pub struct Matcher {
    space: Neighbourhoods,
    search: Search,
    tree: Option<KMeansTree>,
    passes: usize,
}

impl Matcher {
    /// Builds the search structure (the k-means tree, when that search is chosen) over the
    /// exemplar's neighbourhoods (stored plain, or transformed for the wavelet energy).
    #[must_use]
    pub fn over(space: Neighbourhoods, search: Search, rng: &mut Rng) -> Self {
        let tree = (search == Search::KMeansTree).then(|| KMeansTree::build(&space, rng));
        Matcher {
            space,
            search,
            tree,
            passes: PATCHMATCH_PASSES,
        }
    }

    /// Sets the PatchMatch sweeps per M-step (animation frames start from matches carried along
    /// the flow and need fewer than a synthesis from scratch).
    #[must_use]
    pub fn with_passes(mut self, passes: usize) -> Self {
        self.passes = passes.max(1);
        self
    }

    #[must_use]
    pub fn space(&self) -> &Neighbourhoods {
        &self.space
    }

    /// The progress of a new M-step over `nodes` nodes.
    #[must_use]
    pub fn progress(&self, nodes: usize) -> Progress {
        let passes = match self.search {
            Search::PatchMatch => self.passes,
            Search::Exact | Search::KMeansTree => 1,
        };
        Progress::new(nodes, passes)
    }

    /// Improves the matches under `objective` (the plain distance, or with an occurrence
    /// penalty), for queries made one node at a time (with soft-constraint weights when they
    /// carry them), and leaves each match's cost in `costs`: at most `limit` more node visits
    /// from where `progress` stopped, with the same result as one run whatever the limits.
    /// Returns true when the M-step is done.
    #[allow(clippy::too_many_arguments)]
    pub fn resume<Q: Queries + Clone + Send + Sync>(
        &self,
        queries: &mut Q,
        objective: &Objective<'_>,
        grid: QueryGrid<'_>,
        (matches, costs): (&mut [Pos], &mut [f32]),
        rng: &mut Rng,
        progress: &mut Progress,
        limit: usize,
    ) -> bool {
        if self.search == Search::PatchMatch {
            let search = patchmatch::Search {
                space: &self.space,
                objective,
                grid,
            };
            return search.resume(queries, matches, costs, rng, progress, limit);
        }
        let mut query = progress.take_query();
        query.values.resize(self.space.vector_len(), 0.0);
        let mut visited = 0;
        while !progress.is_done() && visited < limit {
            let n = progress.next;
            let (m, d) = (&mut matches[n], &mut costs[n]);
            queries.fill(n, &mut query);
            *d = objective.cost(&self.space, &query, *m, f32::INFINITY);
            let (pos, cost) = match &self.tree {
                // The tree is built for the fall-off weights: it proposes a candidate for the
                // query, which is then scored under the objective, so a match still only
                // changes to a better one.
                Some(tree) => {
                    let pos = tree.nearest(&self.space, &query.values).0;
                    (pos, objective.cost(&self.space, &query, pos, *d))
                }
                None => exact::nearest_by(&self.space, objective, &query),
            };
            if cost < *d {
                if pos != *m {
                    progress.mark_changed(n);
                }
                *m = pos;
                *d = cost;
            }
            visited += 1;
            progress.advance(matches.len());
        }
        progress.put_query(query);
        progress.is_done()
    }
}
