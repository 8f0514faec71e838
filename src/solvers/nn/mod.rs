//! Nearest-neighbourhood search for the M-step: exact brute force (the oracle), the paper's
//! hierarchical k-means tree, and PatchMatch, behind one [`Search`] choice.

pub mod exact;
pub mod kmeans_tree;
pub mod patches;
pub mod patchmatch;

pub use patches::{FeatureMap, InPlace, Neighbourhoods, Pos};

/// One query being searched for: its values and, when it carries weights of its own (soft
/// constraints weigh constrained pixels more, Kwatra et al. 2005 section 4), those; otherwise
/// the space's fall-off applies.
#[derive(Debug, Clone, Default)]
pub struct Query {
    pub values: Vec<f32>,
    pub weights: Vec<f32>,
    pub own_weights: bool,
}

impl Query {
    /// A zeroed query of `len` values under the space's weights.
    #[must_use]
    pub fn new(len: usize) -> Self {
        Query {
            values: vec![0.0; len],
            weights: vec![0.0; len],
            own_weights: false,
        }
    }

    /// A query of the given values under the space's weights.
    #[must_use]
    pub fn of(values: &[f32]) -> Self {
        Query {
            values: values.to_vec(),
            weights: Vec::new(),
            own_weights: false,
        }
    }

    /// The weights its distances use.
    #[inline]
    #[must_use]
    pub fn weights<'a>(&'a self, space: &'a Neighbourhoods) -> &'a [f32] {
        if self.own_weights {
            &self.weights
        } else {
            space.weights()
        }
    }

    /// Its distance to the neighbourhood at `pos` (see [`Neighbourhoods::distance_with`]).
    #[inline]
    #[must_use]
    pub fn distance(&self, space: &Neighbourhoods, pos: Pos, bound: f32) -> f32 {
        space.distance_with(&self.values, self.weights(space), pos, bound)
    }
}

/// The queries of an M-step, one per grid node, made on demand: a 1024x1024 output has 15,625
/// neighbourhoods of 32x32 at spacing 8, 190 MB of RGB queries if stored, and a 4096x4096 one
/// sixteen times that; made one at a time they take one vector.
pub trait Queries {
    /// How many there are.
    fn count(&self) -> usize;
    /// Writes query `n` into `query` (its values, and its weights when it has its own).
    fn fill(&mut self, n: usize, query: &mut Query);
    /// Query `n` where it already lies, when it needs no copy (no transform, no wrapping).
    /// Each pixel lies in 16 neighbourhoods at spacing w/4, so copying every query moved 16
    /// times the output's feature map per sweep.
    fn in_place(&self, _n: usize) -> Option<InPlace<'_>> {
        None
    }
}

/// Queries stored one after another, `len` values each, with optional per-value weights laid
/// out the same way.
#[derive(Debug, Clone, Copy)]
pub struct Stored<'a> {
    pub values: &'a [f32],
    pub weights: Option<&'a [f32]>,
    pub len: usize,
}

impl Queries for Stored<'_> {
    fn count(&self) -> usize {
        self.values.len() / self.len
    }

    fn fill(&mut self, n: usize, query: &mut Query) {
        let range = n * self.len..(n + 1) * self.len;
        query.values.clear();
        query.values.extend_from_slice(&self.values[range.clone()]);
        query.own_weights = self.weights.is_some();
        if let Some(w) = self.weights {
            query.weights.clear();
            query.weights.extend_from_slice(&w[range]);
        }
    }
}

/// Where an M-step stopped: the sweep (PatchMatch makes several; the other searches one) and
/// the next node in it, the nodes whose match changed, and the query buffer. Searches visit
/// nodes in a fixed order, so an M-step can stop after any node and resume later with the same
/// result, which lets a session bound the work of one step on large outputs.
#[derive(Debug, Clone)]
pub struct Progress {
    pub passes: usize,
    pub pass: usize,
    pub next: usize,
    /// Per node, one more than the last sweep in which its match changed (0: not in this
    /// M-step). PatchMatch reads it to skip a propagated candidate it has already tried.
    changed: Vec<u8>,
    query: Query,
    /// PatchMatch: the matches as the sweep under way found them (what propagation reads
    /// across a band's edge), and the seed of the M-step's per-band random streams.
    snapshot: Vec<Pos>,
    seed: u64,
}

impl Progress {
    #[must_use]
    pub fn new(nodes: usize, passes: usize) -> Self {
        Progress {
            passes: if nodes == 0 { 0 } else { passes },
            pass: 0,
            next: 0,
            changed: vec![0; nodes],
            query: Query::default(),
            snapshot: Vec::new(),
            seed: 0,
        }
    }

    /// Moves to the next node of `nodes`, and to the next sweep after the last one.
    pub fn advance(&mut self, nodes: usize) {
        self.next += 1;
        if self.next >= nodes {
            self.next = 0;
            self.pass += 1;
        }
    }

    #[must_use]
    pub fn is_done(&self) -> bool {
        self.pass >= self.passes
    }

    /// Node visits made so far.
    #[must_use]
    pub fn visits(&self) -> usize {
        self.pass * self.changed.len() + self.next
    }

    /// The share of the M-step's node visits done, 0 to 1.
    #[must_use]
    pub fn fraction(&self) -> f64 {
        let nodes = self.changed.len();
        if self.passes == 0 || nodes == 0 {
            return 1.0;
        }
        (self.pass * nodes + self.next) as f64 / (self.passes * nodes) as f64
    }

    /// Records that `node`'s match changed in the sweep under way.
    pub fn mark_changed(&mut self, node: usize) {
        self.changed[node] = u8::try_from(self.pass + 1).unwrap_or(u8::MAX);
    }

    /// Whether `node`'s match changed in sweep `pass` or later.
    #[must_use]
    pub fn changed_since(&self, node: usize, pass: usize) -> bool {
        usize::from(self.changed[node]) > pass
    }

    /// Nodes whose match changed so far.
    #[must_use]
    pub fn changed(&self) -> usize {
        self.changed.iter().filter(|&&c| c > 0).count()
    }

    /// Takes the query buffer out (to fill while the progress is borrowed elsewhere).
    pub fn take_query(&mut self) -> Query {
        std::mem::take(&mut self.query)
    }

    pub fn put_query(&mut self, query: Query) {
        self.query = query;
    }
}

/// What a search minimises: the weighted distance of the query plus a penalty on the candidate
/// (e.g. for exemplar neighbourhoods already used too often). The default is the plain
/// distance.
#[derive(Clone, Copy, Default)]
pub struct Objective<'a> {
    /// A cost added for a candidate, whatever the query.
    pub penalty: Option<Penalties<'a>>,
    /// Candidates the search may not take: an infinite cost where the table is not 0 (for
    /// example exemplar neighbourhoods that reach into a hole being filled). A search only
    /// moves a match to a cheaper candidate, so a match that starts allowed stays allowed.
    pub excluded: Option<Penalties<'a>>,
}

/// A cost per candidate position, `columns` per row: a table rather than a closure, so that the
/// lookup inlines into the search loop (through a `dyn Fn` it would be an indirect call
/// per candidate).
#[derive(Clone, Copy, Debug)]
pub struct Penalties<'a> {
    pub values: &'a [f32],
    pub columns: usize,
}

impl Penalties<'_> {
    #[inline]
    #[must_use]
    pub fn at(&self, z: Pos) -> f32 {
        self.values[z.y as usize * self.columns + z.x as usize]
    }
}

impl Objective<'_> {
    /// The cost of candidate `pos` before any distance: its penalty, infinite when excluded.
    #[inline]
    fn extra(&self, pos: Pos) -> f32 {
        if self.excluded.is_some_and(|e| e.at(pos) != 0.0) {
            return f32::INFINITY;
        }
        self.penalty.map_or(0.0, |p| p.at(pos))
    }

    /// The cost of `pos` for `query`; stops early (returning a value above `bound`) as soon as
    /// it exceeds `bound`.
    #[inline]
    #[must_use]
    pub fn cost(&self, space: &Neighbourhoods, query: &Query, pos: Pos, bound: f32) -> f32 {
        let extra = self.extra(pos);
        if extra > bound || extra == f32::INFINITY {
            return extra;
        }
        extra + query.distance(space, pos, bound - extra)
    }

    /// [`Objective::cost`] of a query read in place (see [`Queries::in_place`]).
    #[inline]
    #[must_use]
    pub fn cost_in_place(
        &self,
        space: &Neighbourhoods,
        query: InPlace<'_>,
        pos: Pos,
        bound: f32,
    ) -> f32 {
        let extra = self.extra(pos);
        if extra > bound || extra == f32::INFINITY {
            return extra;
        }
        extra + space.distance_in_place(query, space.weights(), pos, bound - extra)
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

    /// The search of that name (see [`Search::name`]); `None` for an unknown one.
    #[must_use]
    pub fn from_name(name: &str) -> Option<Search> {
        [Search::Exact, Search::KMeansTree, Search::PatchMatch]
            .into_iter()
            .find(|s| s.name() == name)
    }
}
