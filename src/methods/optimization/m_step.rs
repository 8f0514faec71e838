//! The M-step: for every output neighbourhood x_p, the nearest exemplar neighbourhood z_p, by the
//! chosen search. Every search starts from the current match and only accepts a closer one, so
//! the quadratic energy never rises in an M-step whichever search is used.

use crate::core::Rng;
use crate::solvers::nn::kmeans_tree::KMeansTree;
use crate::solvers::nn::patchmatch::{self, QueryGrid};
use crate::solvers::nn::{
    FeatureMap, Neighbourhoods, Objective, Pos, Queries, Query, Search, exact,
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
    /// Builds the search structure (the k-means tree, when that search is chosen).
    #[must_use]
    pub fn new(exemplar: FeatureMap, size: usize, search: Search, rng: &mut Rng) -> Self {
        Self::over(Neighbourhoods::new(exemplar, size), search, rng)
    }

    /// Over given neighbourhoods (e.g. stored transformed, for the wavelet energy).
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

    /// Improves the matches under `objective` (the plain distance, or with an occurrence
    /// penalty), for queries made one node at a time (with soft-constraint weights when they
    /// carry them), and leaves each match's cost in `costs` (recomputed first: the queries
    /// changed in the E-step). Returns how many matches changed.
    pub fn m_step(
        &self,
        queries: &mut dyn Queries,
        objective: &Objective<'_>,
        grid: QueryGrid<'_>,
        matches: &mut [Pos],
        costs: &mut [f32],
        rng: &mut Rng,
    ) -> usize {
        match self.search {
            Search::PatchMatch => patchmatch::improve(
                &self.space,
                queries,
                objective,
                grid,
                matches,
                costs,
                self.passes,
                rng,
            ),
            Search::Exact | Search::KMeansTree => {
                let mut changed = 0;
                let mut query = Query::new(self.space.vector_len());
                for (n, (m, d)) in matches.iter_mut().zip(costs.iter_mut()).enumerate() {
                    queries.fill(n, &mut query);
                    *d = objective.cost(&self.space, &query, *m, f32::INFINITY);
                    let (pos, cost) = match &self.tree {
                        // The tree is built for the fall-off weights: it proposes a candidate
                        // for the query, which is then scored under the objective, so a match
                        // still only changes to a better one.
                        Some(tree) => {
                            let pos = tree.nearest(&self.space, &query.values).0;
                            (pos, objective.cost(&self.space, &query, pos, *d))
                        }
                        None => exact::nearest_by(&self.space, objective, &query),
                    };
                    if cost < *d {
                        changed += usize::from(pos != *m);
                        *m = pos;
                        *d = cost;
                    }
                }
                changed
            }
        }
    }
}
