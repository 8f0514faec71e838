//! Nearest-neighbourhood search for the M-step: exact brute force (the oracle), the paper's
//! hierarchical k-means tree, and PatchMatch, behind one [`Search`] choice.

pub mod exact;
pub mod kmeans_tree;
pub mod patches;
pub mod patchmatch;

pub use patches::{FeatureMap, Neighbourhoods, Pos};

/// What a search minimises for query `n`: the weighted distance (under the query's own weights
/// when given, e.g. soft constraints) plus a penalty on the candidate (e.g. for exemplar
/// neighbourhoods already used too often). The default is the plain distance.
#[derive(Clone, Copy, Default)]
pub struct Objective<'a> {
    /// Per-value weights for every query, laid out like the queries.
    pub weights: Option<&'a [f32]>,
    /// A cost added for a candidate, whatever the query.
    pub penalty: Option<&'a dyn Fn(Pos) -> f32>,
}

impl Objective<'_> {
    /// The cost of `pos` for query `n`; stops early (returning a value above `bound`) as soon
    /// as it exceeds `bound`.
    #[inline]
    #[must_use]
    pub fn cost(
        &self,
        space: &Neighbourhoods,
        n: usize,
        query: &[f32],
        pos: Pos,
        bound: f32,
    ) -> f32 {
        let extra = self.penalty.map_or(0.0, |f| f(pos));
        if extra > bound {
            return extra;
        }
        let len = space.vector_len();
        let weights = self
            .weights
            .map_or(space.weights(), |w| &w[n * len..(n + 1) * len]);
        extra + space.distance_with(query, weights, pos, bound - extra)
    }
}

/// Which nearest-neighbourhood search the M-step uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Search {
    /// Brute force over every exemplar neighbourhood: exact, slow for large exemplars.
    Exact,
    /// Hierarchical k-means tree (k = 4, leaves under 1%): the paper's search.
    KMeansTree,
    /// PatchMatch warm-started from the previous matches: the fastest.
    #[default]
    PatchMatch,
}

impl Search {
    /// The names used in options and in the benchmark's tables.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Search::Exact => "exact",
            Search::KMeansTree => "kmeans-tree",
            Search::PatchMatch => "patchmatch",
        }
    }

    #[must_use]
    pub fn from_name(name: &str) -> Option<Search> {
        [Search::Exact, Search::KMeansTree, Search::PatchMatch]
            .into_iter()
            .find(|s| s.name() == name)
    }
}
