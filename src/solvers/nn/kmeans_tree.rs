//! The hierarchical k-means tree of Kwatra et al. 2005 (section 3, M-step): k-means with k = 4 at
//! every node over the neighbourhoods it holds, recursing until a node holds fewer than 1% of all
//! neighbourhoods. Leaves keep neighbourhood *locations*, not copies: vectors are read from the
//! exemplar on the fly, so a 32x32 neighbourhood costs 8 bytes in the tree, not 4 KiB.
//!
//! A query descends to the nearest centroid at each level and searches its leaf exactly; to make
//! up for a query that sits near a cluster boundary, it then visits the next-best branches in
//! order of centroid distance (best-bin-first) until [`LEAVES_SEARCHED`] leaves are done. This is
//! still approximate; the caller keeps the previous match when it is closer.

use super::patches::{Neighbourhoods, Pos, weighted_ssd};
use crate::core::Rng;

/// Branching factor (the paper's k).
pub const K: usize = 4;
/// Leaves a query visits. One is the paper's plain descent; a few more cost little (a leaf is 1%
/// of the neighbourhoods) and catch queries that fall near a boundary between clusters.
pub const LEAVES_SEARCHED: usize = 3;
/// Lloyd iterations per split: the clusters only have to route queries, not be optimal.
const LLOYD_ITERATIONS: usize = 5;

#[derive(Debug, Clone)]
enum Node {
    /// `K` children; the centroid of child `c` is `centroids[first_centroid + c]`.
    Inner {
        children: [u32; K],
        first_centroid: u32,
    },
    /// A range of `positions`.
    Leaf { start: u32, len: u32 },
}

/// The tree over all neighbourhoods of one exemplar at one neighbourhood size.
#[derive(Debug, Clone)]
pub struct KMeansTree {
    nodes: Vec<Node>,
    /// Centroid vectors, `vector_len` each, in the order `first_centroid` refers to.
    centroids: Vec<f32>,
    /// Leaf members, grouped so that each leaf is one contiguous range.
    positions: Vec<Pos>,
    vector_len: usize,
}

impl KMeansTree {
    /// Builds the tree; leaves hold at most `max(1, count / 100)` neighbourhoods (1%, as in the
    /// paper).
    #[must_use]
    pub fn build(space: &Neighbourhoods, rng: &mut Rng) -> Self {
        let leaf_limit = (space.count() / 100).max(1);
        Self::build_with_leaf_limit(space, leaf_limit, rng)
    }

    #[must_use]
    pub fn build_with_leaf_limit(space: &Neighbourhoods, leaf_limit: usize, rng: &mut Rng) -> Self {
        let mut tree = KMeansTree {
            nodes: Vec::new(),
            centroids: Vec::new(),
            positions: (0..space.count()).map(|i| space.pos_of(i)).collect(),
            vector_len: space.vector_len(),
        };
        let count = tree.positions.len();
        let mut scratch = Scratch::new(space.vector_len());
        tree.build_node(space, 0, count, leaf_limit.max(1), rng, &mut scratch);
        tree
    }

    /// Number of leaves (for tests and the teaching view).
    #[must_use]
    pub fn leaf_sizes(&self) -> Vec<usize> {
        self.nodes
            .iter()
            .filter_map(|n| match n {
                Node::Leaf { len, .. } => Some(*len as usize),
                Node::Inner { .. } => None,
            })
            .collect()
    }

    /// Splits `positions[start..start + len]` and returns the new node's index.
    fn build_node(
        &mut self,
        space: &Neighbourhoods,
        start: usize,
        len: usize,
        leaf_limit: usize,
        rng: &mut Rng,
        scratch: &mut Scratch,
    ) -> u32 {
        let index = self.nodes.len() as u32;
        self.nodes.push(Node::Leaf {
            start: start as u32,
            len: len as u32,
        });
        if len <= leaf_limit {
            return index;
        }
        let members = &mut self.positions[start..start + len];
        let Some(sizes) = kmeans(space, members, rng, scratch) else {
            return index; // all members identical: nothing to split
        };
        let first_centroid = (self.centroids.len() / self.vector_len) as u32;
        self.centroids.extend_from_slice(&scratch.centroids);
        let mut children = [0u32; K];
        let mut offset = start;
        for (c, &size) in sizes.iter().enumerate() {
            children[c] = self.build_node(space, offset, size, leaf_limit, rng, scratch);
            offset += size;
        }
        self.nodes[index as usize] = Node::Inner {
            children,
            first_centroid,
        };
        index
    }

    /// The nearest neighbourhood among the [`LEAVES_SEARCHED`] leaves whose branches are closest to
    /// the query, and its distance.
    #[must_use]
    pub fn nearest(&self, space: &Neighbourhoods, query: &[f32]) -> (Pos, f32) {
        let weights = space.weights();
        let mut best = (self.positions[0], f32::INFINITY);
        // Unvisited branches, as (distance of the query to the branch's centroid, node). Tiny, so
        // a vector scanned for its minimum beats a heap.
        let mut pending: Vec<(f32, u32)> = vec![(0.0, 0)];
        let mut leaves = 0;
        while leaves < LEAVES_SEARCHED {
            let Some(at) =
                (0..pending.len()).min_by(|&a, &b| pending[a].0.total_cmp(&pending[b].0))
            else {
                break;
            };
            let mut node = pending.swap_remove(at).1 as usize;
            // Greedy descent, remembering the siblings not taken.
            while let Node::Inner {
                children,
                first_centroid,
            } = self.nodes[node]
            {
                let mut nearest = (0usize, f32::INFINITY);
                for (c, &child) in children.iter().enumerate() {
                    let from = (first_centroid as usize + c) * self.vector_len;
                    let d = weighted_ssd(
                        query,
                        &self.centroids[from..from + self.vector_len],
                        weights,
                    );
                    pending.push((d, child));
                    if d < nearest.1 {
                        nearest = (pending.len() - 1, d);
                    }
                }
                node = pending.swap_remove(nearest.0).1 as usize;
            }
            if let Node::Leaf { start, len } = self.nodes[node] {
                for &pos in &self.positions[start as usize..(start + len) as usize] {
                    let d = space.distance(query, pos, best.1);
                    if d < best.1 {
                        best = (pos, d);
                    }
                }
            }
            leaves += 1;
        }
        best
    }
}

/// Buffers reused across every split of a build.
struct Scratch {
    centroids: Vec<f32>,
    sums: Vec<f64>,
    assignment: Vec<u8>,
    row: Vec<f32>,
}

impl Scratch {
    fn new(vector_len: usize) -> Self {
        Scratch {
            centroids: vec![0.0; K * vector_len],
            sums: vec![0.0; K * vector_len],
            assignment: Vec::new(),
            row: vec![0.0; vector_len],
        }
    }
}

/// Lloyd's k-means over `members`, which it reorders so that each cluster is contiguous. Leaves
/// the centroids in `scratch.centroids` and returns the cluster sizes, or `None` if the members
/// cannot be split (fewer than two distinct vectors).
fn kmeans(
    space: &Neighbourhoods,
    members: &mut [Pos],
    rng: &mut Rng,
    s: &mut Scratch,
) -> Option<[usize; K]> {
    let n = space.vector_len();
    let weights = space.weights();
    // Seeds: K distinct members chosen at random, drawn without replacement by a partial
    // Fisher-Yates shuffle of `members` (reordered below anyway). A repeated seed would only
    // leave its cluster empty. With fewer than K members, the extra seeds repeat the first ones.
    for c in 0..K.min(members.len()) {
        let pick = c + rng.index(members.len() - c);
        members.swap(c, pick);
    }
    for c in 0..K {
        let seed = members[c % members.len()];
        space.copy_to(seed, &mut s.centroids[c * n..(c + 1) * n]);
    }
    s.assignment.clear();
    s.assignment.resize(members.len(), 0);
    let mut sizes = [0usize; K];
    for _ in 0..LLOYD_ITERATIONS {
        sizes = [0; K];
        s.sums.iter_mut().for_each(|v| *v = 0.0);
        for (m, &pos) in members.iter().enumerate() {
            space.copy_to(pos, &mut s.row);
            let mut best = (0usize, f32::INFINITY);
            for c in 0..K {
                let d = weighted_ssd(&s.row, &s.centroids[c * n..(c + 1) * n], weights);
                if d < best.1 {
                    best = (c, d);
                }
            }
            s.assignment[m] = best.0 as u8;
            sizes[best.0] += 1;
            for (sum, &v) in s.sums[best.0 * n..(best.0 + 1) * n].iter_mut().zip(&s.row) {
                *sum += f64::from(v);
            }
        }
        for (c, &size) in sizes.iter().enumerate() {
            if size > 0 {
                for (centroid, sum) in s.centroids[c * n..(c + 1) * n]
                    .iter_mut()
                    .zip(&s.sums[c * n..])
                {
                    *centroid = (*sum / size as f64) as f32;
                }
            } else {
                // An empty cluster takes a random member, so the next iteration can use it.
                let pick = members[rng.index(members.len())];
                space.copy_to(pick, &mut s.centroids[c * n..(c + 1) * n]);
            }
        }
    }
    if sizes.iter().filter(|&&size| size > 0).count() < 2 {
        return None;
    }
    // Stable grouping by cluster: a counting sort of the members.
    let mut starts = [0usize; K];
    for c in 1..K {
        starts[c] = starts[c - 1] + sizes[c - 1];
    }
    let mut grouped = vec![Pos::default(); members.len()];
    for (m, &pos) in members.iter().enumerate() {
        let c = s.assignment[m] as usize;
        grouped[starts[c]] = pos;
        starts[c] += 1;
    }
    members.copy_from_slice(&grouped);
    Some(sizes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solvers::nn::exact;
    use crate::solvers::nn::patches::FeatureMap;

    /// Smoothed noise: structured like a photograph, so that clusters mean something.
    fn space(width: usize, height: usize, size: usize) -> Neighbourhoods {
        let mut rng = Rng::new(11);
        let mut data: Vec<f32> = (0..width * height * 3).map(|_| rng.next_f32()).collect();
        for _ in 0..3 {
            for i in 3..data.len() {
                data[i] = 0.5 * (data[i] + data[i - 3]);
            }
            for i in width * 3..data.len() {
                data[i] = 0.5 * (data[i] + data[i - width * 3]);
            }
        }
        Neighbourhoods::new(
            FeatureMap {
                width,
                height,
                dims: 3,
                data,
            },
            size,
        )
    }

    #[test]
    fn every_neighbourhood_lands_in_exactly_one_small_leaf() {
        let space = space(40, 40, 6);
        let tree = KMeansTree::build(&space, &mut Rng::new(1));
        let sizes = tree.leaf_sizes();
        assert_eq!(sizes.iter().sum::<usize>(), space.count());
        let mut seen: Vec<Pos> = tree.positions.clone();
        seen.sort_by_key(|p| (p.y, p.x));
        seen.dedup();
        assert_eq!(seen.len(), space.count());
        assert!(sizes.len() > 10, "{} leaves", sizes.len());
    }

    #[test]
    fn finds_planted_neighbourhoods_and_stays_close_to_exact_on_noisy_ones() {
        let space = space(48, 48, 8);
        let tree = KMeansTree::build(&space, &mut Rng::new(2));
        let mut q = vec![0.0; space.vector_len()];
        let mut rng = Rng::new(4);
        let (mut tree_total, mut exact_total) = (0.0, 0.0);
        for i in 0..40 {
            let planted = space.pos_of(rng.index(space.count()));
            space.copy_to(planted, &mut q);
            if i < 20 {
                // A planted query is its own leaf member: found exactly.
                assert_eq!(tree.nearest(&space, &q), (planted, 0.0));
            } else {
                q.iter_mut()
                    .for_each(|v| *v += (rng.next_f32() - 0.5) * 0.05);
                tree_total += tree.nearest(&space, &q).1;
                exact_total += exact::nearest(&space, &q).1;
            }
        }
        assert!(
            tree_total <= exact_total * 1.25,
            "tree {tree_total} vs exact {exact_total}"
        );
    }

    #[test]
    fn k_different_neighbourhoods_split_into_k_single_leaves() {
        // K members, all different, and leaves of one: distinct seeds give each member its own
        // cluster at the first split. Seeds drawn with replacement repeat a member 91% of the
        // time (1 - 4!/4^4), leaving a cluster empty.
        let space = space(5, 5, 4);
        assert_eq!(space.count(), K);
        for seed in 0..64 {
            let tree = KMeansTree::build_with_leaf_limit(&space, 1, &mut Rng::new(seed));
            assert_eq!(tree.leaf_sizes(), [1; K], "seed {seed}");
        }
    }

    #[test]
    fn a_flat_exemplar_does_not_recurse_forever() {
        let flat = Neighbourhoods::new(
            FeatureMap {
                width: 30,
                height: 30,
                dims: 1,
                data: vec![0.5; 900],
            },
            4,
        );
        let tree = KMeansTree::build(&flat, &mut Rng::new(0));
        assert_eq!(tree.leaf_sizes(), vec![flat.count()]);
        assert_eq!(tree.nearest(&flat, &[0.5; 16]).1, 0.0);
    }
}
