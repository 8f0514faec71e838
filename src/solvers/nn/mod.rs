//! Nearest-neighbourhood search for the M-step: exact brute force (the oracle), the paper's
//! hierarchical k-means tree, and PatchMatch, behind one [`Search`] choice.

pub mod exact;
pub mod kmeans_tree;
pub mod patches;
pub mod patchmatch;

pub use patches::{FeatureMap, Neighbourhoods, Pos};

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
