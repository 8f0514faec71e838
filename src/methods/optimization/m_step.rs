//! The M-step: for every output neighbourhood x_p, the nearest exemplar neighbourhood z_p, by the
//! chosen search. Every search starts from the current match and only accepts a closer one, so
//! the quadratic energy never rises in an M-step whichever search is used.

use crate::core::Rng;
use crate::solvers::nn::kmeans_tree::KMeansTree;
use crate::solvers::nn::patchmatch::{self, QueryGrid};
use crate::solvers::nn::{FeatureMap, Neighbourhoods, Objective, Pos, Search, exact};

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

    /// Recomputes `costs` for the current `matches` (the queries changed in the E-step), then
    /// improves the matches under `objective` (the plain distance, or with soft-constraint
    /// weights and an occurrence penalty). Returns how many matches changed.
    pub fn m_step(
        &self,
        queries: &[f32],
        objective: &Objective<'_>,
        grid: QueryGrid<'_>,
        matches: &mut [Pos],
        costs: &mut [f32],
        rng: &mut Rng,
    ) -> usize {
        let len = self.space.vector_len();
        for (n, (m, d)) in matches.iter().zip(costs.iter_mut()).enumerate() {
            *d = objective.cost(
                &self.space,
                n,
                &queries[n * len..(n + 1) * len],
                *m,
                f32::INFINITY,
            );
        }
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
                for (n, (m, d)) in matches.iter_mut().zip(costs.iter_mut()).enumerate() {
                    let query = &queries[n * len..(n + 1) * len];
                    let (pos, cost) = match &self.tree {
                        // The tree is built for the fall-off weights: it proposes a candidate
                        // for the query, which is then scored under the objective, so a match
                        // still only changes to a better one.
                        Some(tree) => {
                            let pos = tree.nearest(&self.space, query).0;
                            (pos, objective.cost(&self.space, n, query, pos, *d))
                        }
                        None => exact::nearest_by(&self.space, objective, n, query),
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
