//! PatchMatch (Barnes et al. 2009) over the sparse grid of output neighbourhoods: each grid node
//! tries its neighbours' matches shifted by the grid offset (propagation), then, in the first
//! sweep of an M-step, random candidates around its own match at halving radii (random search).
//! Warm-started from the previous iteration's matches, so the EM iterations double as PatchMatch
//! iterations.

use super::patches::{Neighbourhoods, Pos};
use super::{Objective, Progress, Queries, Query};
use crate::core::{Rng, parallel};

/// The layout of the query grid: column and row positions (in output pixels) of the nodes. Nodes
/// are stored row by row; query `i` is node `(i % cols.len(), i / cols.len())`.
#[derive(Debug, Clone, Copy)]
pub struct QueryGrid<'a> {
    pub cols: &'a [usize],
    pub rows: &'a [usize],
}

/// Node rows in a band of a sweep. A sweep searches its bands in parallel (with the `parallel`
/// feature), each in scan order (reversed in backward sweeps). Propagation inside a band reads
/// the matches it has just improved, as one sweep over the grid does; across a band's edge it
/// reads the neighbour's match from the start of the sweep, and random search draws from the
/// band's own stream. So a band never reads what another band writes in the same sweep, and
/// the matches are the same at any thread count. Eight rows: at 1024x1024 and neighbourhoods
/// of 8 (a node every 2 pixels) a band is 4,096 nodes, and a step's share of an M-step (about
/// 10,000 visits) is several bands.
pub const BAND_ROWS: usize = 8;

/// Improves `matches` in place by `passes` alternating forward/backward sweeps and leaves their
/// costs in `distances` (the first sweep computes each node's cost for its current match when
/// it gets there: the queries changed since the last M-step). A match only ever changes to a
/// strictly closer one, so the cost cannot rise. Costs are those of `objective` (the plain
/// distance by default). Queries are made one node at a time. Returns how many nodes changed.
#[allow(clippy::too_many_arguments)]
pub fn improve<Q: Queries + Clone + Send + Sync>(
    space: &Neighbourhoods,
    queries: &Q,
    objective: &Objective<'_>,
    grid: QueryGrid<'_>,
    matches: &mut [Pos],
    distances: &mut [f32],
    passes: usize,
    rng: &mut Rng,
) -> usize {
    let mut progress = Progress::new(matches.len(), passes);
    let search = Search {
        space,
        objective,
        grid,
    };
    search.resume(queries, matches, distances, rng, &mut progress, usize::MAX);
    progress.changed()
}

/// What a PatchMatch M-step searches over.
#[derive(Clone, Copy)]
pub struct Search<'a> {
    pub space: &'a Neighbourhoods,
    pub objective: &'a Objective<'a>,
    pub grid: QueryGrid<'a>,
}

/// One band of a sweep: its first node, and its nodes' matches, costs and change marks.
struct Band<'a> {
    index: usize,
    start: usize,
    matches: &'a mut [Pos],
    distances: &'a mut [f32],
    changed: &'a mut [u8],
}

impl Search<'_> {
    /// [`improve`] in parts: visits whole bands of nodes from where `progress` stopped, about
    /// `limit` visits, in whole bands and at least [`parallel::MIN_ROUNDS`] bands per thread (the sweeps run in a fixed
    /// order and bands do not depend on each other within a sweep, so stopping and resuming
    /// gives the same matches as one run). Returns true when every sweep is done.
    pub fn resume<Q: Queries + Clone + Send + Sync>(
        &self,
        queries: &Q,
        matches: &mut [Pos],
        distances: &mut [f32],
        rng: &mut Rng,
        progress: &mut Progress,
        limit: usize,
    ) -> bool {
        let nodes = matches.len();
        let band_len = BAND_ROWS * self.grid.cols.len();
        let mut visited = 0;
        while progress.pass < progress.passes && visited < limit {
            if progress.next == 0 {
                if progress.pass == 0 {
                    // The M-step's random streams, one per band, from one draw.
                    progress.seed = rng.next_u64();
                }
                progress.snapshot.clear();
                progress.snapshot.extend_from_slice(matches);
            }
            let pass = progress.pass;
            // Bands in a batch: what `limit` asks for, in whole rounds of the threads and at
            // least MIN_ROUNDS of them, so that bands of uneven cost even out over the threads
            // (where a batch ends changes no match).
            let threads = parallel::threads();
            let bands = (limit - visited)
                .div_ceil(band_len)
                .div_ceil(threads)
                .max(parallel::MIN_ROUNDS)
                .saturating_mul(threads);
            let range =
                progress.next..nodes.min(progress.next.saturating_add(bands.saturating_mul(band_len)));
            let first_band = progress.next / band_len;
            let Progress {
                changed,
                snapshot,
                seed,
                ..
            } = progress;
            let mut bands: Vec<Band<'_>> = matches[range.clone()]
                .chunks_mut(band_len)
                .zip(distances[range.clone()].chunks_mut(band_len))
                .zip(changed[range.clone()].chunks_mut(band_len))
                .enumerate()
                .map(|(k, ((matches, distances), changed))| Band {
                    index: first_band + k,
                    start: range.start + k * band_len,
                    matches,
                    distances,
                    changed,
                })
                .collect();
            let (snapshot, seed) = (&snapshot[..], *seed);
            parallel::for_each_piece_mut(&mut bands, 1, |_, band| {
                self.sweep_band(queries, pass, &mut band[0], snapshot, seed);
            });
            visited += range.len();
            progress.next = range.end;
            if progress.next >= nodes {
                progress.next = 0;
                progress.pass += 1;
            }
        }
        progress.is_done()
    }

    /// Sweep `pass` over one band's nodes.
    fn sweep_band<Q: Queries + Clone>(
        &self,
        queries: &Q,
        pass: usize,
        band: &mut Band<'_>,
        snapshot: &[Pos],
        seed: u64,
    ) {
        let Search {
            space,
            objective,
            grid,
        } = *self;
        let mut queries = queries.clone();
        let mut query = Query::default();
        let mut rng = Rng::with_stream(seed, band.index as u64);
        let (nx, ny) = (grid.cols.len(), grid.rows.len());
        let (ex, ey) = space.extent();
        let max_radius = ex.max(ey) as i64;
        let forward = pass.is_multiple_of(2);
        let step: isize = if forward { 1 } else { -1 };
        let len = band.matches.len();
        let own = band.start..band.start + len;
        for k in 0..len {
            let local = if forward { k } else { len - 1 - k };
            let i = band.start + local;
            let (gx, gy) = (i % nx, i / nx);
            if queries.in_place(i).is_none() {
                queries.fill(i, &mut query);
            }
            let in_place = queries.in_place(i);
            let cost = |candidate: Pos, bound: f32| match in_place {
                Some(rows) => objective.cost_in_place(space, rows, candidate, bound),
                None => objective.cost(space, &query, candidate, bound),
            };
            if pass == 0 {
                band.distances[local] = cost(band.matches[local], f32::INFINITY);
            }
            let mut best = (band.matches[local], band.distances[local]);
            let consider = |candidate: Pos, best: &mut (Pos, f32)| {
                if candidate != best.0 {
                    let d = cost(candidate, best.1);
                    if d < best.1 {
                        *best = (candidate, d);
                    }
                }
            };
            // Propagation from the already-visited horizontal and vertical neighbours: in this
            // band, their matches as this sweep left them; past its edge, as the sweep found
            // them. In this band, the sweep two before this one ran in the same direction,
            // against the same queries and costs, and tried the same neighbours' candidates: a
            // neighbour whose match has not changed since then offers one that lost already and
            // would lose again (this node's best only got closer), so it is not measured twice.
            let neighbour = |j: usize| -> Option<Pos> {
                if !own.contains(&j) {
                    return Some(snapshot[j]);
                }
                let tried = pass >= 2 && usize::from(band.changed[j - band.start]) < pass;
                (!tried).then(|| band.matches[j - band.start])
            };
            let qx = gx as isize - step;
            if (0..nx as isize).contains(&qx)
                && let Some(m) = neighbour(gy * nx + qx as usize)
            {
                let shift = grid.cols[gx] as i64 - grid.cols[qx as usize] as i64;
                consider(space.clamp_from(m, shift, 0), &mut best);
            }
            let qy = gy as isize - step;
            if (0..ny as isize).contains(&qy)
                && let Some(m) = neighbour(qy as usize * nx + gx)
            {
                let shift = grid.rows[gy] as i64 - grid.rows[qy as usize] as i64;
                consider(space.clamp_from(m, 0, shift), &mut best);
            }
            // Random search around the current best, radius halving down to one pixel, in the
            // first sweep of an M-step only. The queries are fixed for the whole M-step, and a
            // node's random candidates in later sweeps almost never win: at the finest level of
            // a 1024x1024 synthesis each radius won 0.01-0.3% of its tries in the second and
            // third sweeps, against 2-16% for propagation, while the seven radii made over
            // 90% of all evaluations. The later sweeps spread what the first one found, and the next
            // M-step searches at random again: over the EM iterations every node still gets a
            // random search per M-step, as in Barnes et al.'s one per iteration.
            let mut radius = if pass == 0 { max_radius } else { 0 };
            while radius >= 1 {
                let span = (2 * radius + 1) as u32;
                let dx = i64::from(rng.below(span)) - radius;
                let dy = i64::from(rng.below(span)) - radius;
                consider(space.clamp_from(best.0, dx, dy), &mut best);
                radius /= 2;
            }
            if best.0 != band.matches[local] {
                band.changed[local] = u8::try_from(pass + 1).unwrap_or(u8::MAX);
            }
            band.matches[local] = best.0;
            band.distances[local] = best.1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solvers::nn::patches::FeatureMap;
    use crate::solvers::nn::{Stored, exact};

    /// A smooth but non-repeating exemplar, so that nearest neighbourhoods are well defined.
    fn exemplar(width: usize, height: usize) -> FeatureMap {
        let mut rng = Rng::new(5);
        let mut data: Vec<f32> = (0..width * height).map(|_| rng.next_f32()).collect();
        for _ in 0..2 {
            for y in 0..height {
                for x in 1..width {
                    data[y * width + x] = 0.5 * (data[y * width + x] + data[y * width + x - 1]);
                }
            }
        }
        FeatureMap {
            width,
            height,
            dims: 1,
            data,
        }
    }

    /// A grid of `nodes` (columns, rows) two pixels apart, and its queries cut from the space
    /// at `source(x, y)` of each node's corner.
    fn cut_queries(
        space: &Neighbourhoods,
        nodes: (usize, usize),
        source: impl Fn(usize, usize) -> Pos,
    ) -> (Vec<usize>, Vec<usize>, Vec<f32>) {
        let cols: Vec<usize> = (0..nodes.0).map(|i| i * 2).collect();
        let rows: Vec<usize> = (0..nodes.1).map(|i| i * 2).collect();
        let len = space.vector_len();
        let mut queries = vec![0.0; cols.len() * rows.len() * len];
        for (k, out) in queries.chunks_exact_mut(len).enumerate() {
            space.copy_to(source(cols[k % nodes.0], rows[k / nodes.0]), out);
        }
        (cols, rows, queries)
    }

    /// [`improve`] over stored queries of `len` values, with the plain distance.
    #[allow(clippy::too_many_arguments)]
    fn improve_stored(
        space: &Neighbourhoods,
        queries: &[f32],
        len: usize,
        grid: QueryGrid<'_>,
        matches: &mut [Pos],
        distances: &mut [f32],
        passes: usize,
        rng: &mut Rng,
    ) -> usize {
        let stored = Stored {
            values: queries,
            weights: None,
            len,
        };
        let objective = Objective::default();
        improve(
            space,
            &stored,
            &objective,
            grid,
            matches,
            distances,
            passes,
            rng,
        )
    }

    #[test]
    fn recovers_a_shifted_copy_exactly_like_exact_search() {
        // The output is a crop of the exemplar: every query has a zero-distance match, and
        // propagation should carry one lucky hit across the whole grid.
        let space = Neighbourhoods::new(exemplar(48, 40), 6);
        let (cols, rows, queries) = cut_queries(&space, (8, 6), |x, y| Pos::new(x + 20, y + 15));
        let len = space.vector_len();
        let mut rng = Rng::new(9);
        let mut matches: Vec<Pos> = (0..48)
            .map(|_| space.clamp(rng.below(43).into(), rng.below(35).into()))
            .collect();
        let mut distances: Vec<f32> = matches
            .iter()
            .enumerate()
            .map(|(k, &m)| space.distance(&queries[k * len..(k + 1) * len], m, f32::INFINITY))
            .collect();
        let grid = QueryGrid {
            cols: &cols,
            rows: &rows,
        };
        for _ in 0..6 {
            improve_stored(
                &space,
                &queries,
                len,
                grid,
                &mut matches,
                &mut distances,
                2,
                &mut rng,
            );
        }
        for (k, d) in distances.iter().enumerate() {
            let (_, exact_d) = exact::nearest(&space, &queries[k * len..(k + 1) * len]);
            assert!(*d <= exact_d + 1e-6, "node {k}: {d} vs exact {exact_d}");
        }
    }

    #[test]
    fn propagation_carries_a_stacked_copy_but_random_search_stays_in_its_own() {
        // Two copies as sub-pixel matching stacks them: the map, and the map half a pixel to
        // the right (the mean of horizontal neighbours). The queries are cut from the second
        // copy; one node starts on its exact match there, the others in the first copy. Only
        // propagation crosses copies (a node's phase comes from the flow or its neighbours,
        // never from a random jump), and it carries the exact match to every node.
        let map = exemplar(40, 36);
        let mut half = map.clone();
        for y in 0..36 {
            for x in 0..40 {
                let right = map.data[y * 40 + (x + 1).min(39)];
                half.data[y * 40 + x] = 0.5 * (map.data[y * 40 + x] + right);
            }
        }
        let space = Neighbourhoods::stacked(&[map, half], 6);
        let (cols, rows, queries) = cut_queries(&space, (6, 5), |x, y| {
            space.in_copy(1, Pos::new(x + 14, y + 11))
        });
        let len = space.vector_len();
        let mut rng = Rng::new(5);
        let mut matches: Vec<Pos> = (0..30)
            .map(|_| space.clamp(rng.below(35).into(), rng.below(31).into()))
            .collect();
        let run = |matches: &mut Vec<Pos>, rng: &mut Rng| {
            let mut distances = vec![f32::INFINITY; 30];
            improve_stored(
                &space,
                &queries,
                len,
                QueryGrid {
                    cols: &cols,
                    rows: &rows,
                },
                matches,
                &mut distances,
                4,
                rng,
            );
            distances
        };
        let alone = run(&mut matches.clone(), &mut rng);
        assert!(
            alone.iter().all(|&d| d > 1e-6),
            "no exact match in the first copy"
        );
        matches[0] = space.in_copy(1, Pos::new(14, 11));
        let distances = run(&mut matches, &mut rng);
        let (_, ny) = space.extent();
        for (k, (&m, &d)) in matches.iter().zip(&distances).enumerate() {
            let (copy, local) = space.copy_of(m);
            assert!((local.y as usize) < ny, "node {k} straddles: {m:?}");
            assert!(copy == 1 && d < 1e-9, "node {k}: {m:?} at {d}");
        }
    }

    #[test]
    fn only_the_first_sweep_searches_at_random() {
        // Random search is the only use of the generator, so three sweeps must draw exactly
        // what one draws, while the later sweeps still propagate (and change matches).
        let space = Neighbourhoods::new(exemplar(48, 40), 6);
        let (cols, rows, queries) = cut_queries(&space, (10, 8), |x, y| Pos::new(x + 9, y + 7));
        let len = space.vector_len();
        let grid = QueryGrid {
            cols: &cols,
            rows: &rows,
        };
        let mut start_rng = Rng::new(11);
        let start: Vec<Pos> = (0..80)
            .map(|_| space.clamp(start_rng.below(43).into(), start_rng.below(35).into()))
            .collect();
        let run = |passes: usize| {
            let mut rng = Rng::new(4);
            let mut matches = start.clone();
            let mut distances = vec![f32::INFINITY; 80];
            improve_stored(
                &space,
                &queries,
                len,
                grid,
                &mut matches,
                &mut distances,
                passes,
                &mut rng,
            );
            (matches, distances.iter().sum::<f32>(), rng)
        };
        let (one, one_cost, one_rng) = run(1);
        let (three, three_cost, three_rng) = run(3);
        assert_eq!(one_rng, three_rng, "the later sweeps drew random numbers");
        assert_ne!(one, three, "the later sweeps propagated nothing");
        assert!(three_cost < one_cost, "{three_cost} vs {one_cost}");
    }

    #[test]
    fn never_makes_a_match_worse_and_reaches_near_exact_on_random_queries() {
        let space = Neighbourhoods::new(exemplar(64, 64), 8);
        let (cols, rows): (Vec<usize>, Vec<usize>) = (
            (0..12).map(|i| i * 2).collect(),
            (0..12).map(|i| i * 2).collect(),
        );
        let len = space.vector_len();
        let mut rng = Rng::new(3);
        let queries: Vec<f32> = (0..144 * len)
            .map(|_| rng.next_f32() * 0.5 + 0.25)
            .collect();
        let mut matches = vec![Pos::default(); 144];
        let mut distances: Vec<f32> = (0..144)
            .map(|k| {
                space.distance(
                    &queries[k * len..(k + 1) * len],
                    Pos::default(),
                    f32::INFINITY,
                )
            })
            .collect();
        let grid = QueryGrid {
            cols: &cols,
            rows: &rows,
        };
        let mut previous = distances.clone();
        for _ in 0..8 {
            improve_stored(
                &space,
                &queries,
                len,
                grid,
                &mut matches,
                &mut distances,
                2,
                &mut rng,
            );
            assert!(distances.iter().zip(&previous).all(|(d, p)| d <= p));
            previous.clone_from(&distances);
        }
        let exact_total: f32 = (0..144)
            .map(|k| exact::nearest(&space, &queries[k * len..(k + 1) * len]).1)
            .sum();
        let pm_total: f32 = distances.iter().sum();
        // Independent random queries have no coherent structure to propagate, the hardest case
        // for PatchMatch (in synthesis, neighbouring queries overlap and propagation does the
        // work, see the test above); the stated margin here is 25% of the exact energy.
        assert!(
            pm_total <= exact_total * 1.25,
            "patchmatch {pm_total} vs exact {exact_total}"
        );
    }
}
