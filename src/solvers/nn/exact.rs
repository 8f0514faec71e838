//! Exact nearest neighbourhood by brute force: every exemplar neighbourhood is compared. The
//! oracle for the faster searches, and fine for small exemplars.

use super::patches::{Neighbourhoods, Pos};
use super::{Objective, Query};

/// The nearest neighbourhood to `query` and its distance. Ties go to the first in scan order, so
/// the answer is deterministic. The running best is the early-exit bound of every comparison.
#[must_use]
pub fn nearest(space: &Neighbourhoods, query: &[f32]) -> (Pos, f32) {
    nearest_by(space, &Objective::default(), &Query::of(query))
}

/// The candidate of least `objective` cost for `query`.
#[must_use]
pub fn nearest_by(space: &Neighbourhoods, objective: &Objective<'_>, query: &Query) -> (Pos, f32) {
    let mut best = (Pos::default(), f32::INFINITY);
    for i in 0..space.count() {
        let pos = space.pos_of(i);
        let d = objective.cost(space, query, pos, best.1);
        if d < best.1 {
            best = (pos, d);
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solvers::nn::patches::FeatureMap;

    #[test]
    fn finds_a_planted_neighbourhood() {
        let mut rng = crate::core::Rng::new(12);
        let data = (0..20 * 16 * 3).map(|_| rng.next_f32()).collect();
        let space = Neighbourhoods::new(
            FeatureMap {
                width: 20,
                height: 16,
                dims: 3,
                data,
            },
            5,
        );
        for planted in [Pos::new(0, 0), Pos::new(15, 11), Pos::new(7, 3)] {
            let mut q = vec![0.0; space.vector_len()];
            space.copy_to(planted, &mut q);
            q.iter_mut().for_each(|v| *v += 0.001); // a little noise: still the nearest
            let (pos, d) = nearest(&space, &q);
            assert_eq!(pos, planted);
            assert!(d < 1e-3);
        }
    }
}
