//! Graph-cut texture tests: seams against the cost the paper defines, placement rules, coverage,
//! determinism, blending.

use super::canvas::{Patch, UNCOVERED};
use super::options::{Blend, Options, Placement, Transforms};
use super::seam_graph::{SeamGraph, SeamGrid};
use super::session::Session;
use super::synthesis::Synthesis;
use crate::core::testing::{noise, sample};
use crate::core::{Image, Rng};

/// Every covered pixel shows exactly what its patch's source has at that place.
pub(super) fn assert_pixels_match_labels(s: &Synthesis) {
    let w = s.canvas.width;
    for (i, &label) in s.canvas.label.iter().enumerate() {
        if label == UNCOVERED {
            continue;
        }
        let patch = s.canvas.patches[label as usize];
        let source = &s.sources[patch.source as usize];
        let (sx, sy) = s
            .source_coords(patch, i % w, i / w)
            .expect("the patch covers its pixels");
        assert_eq!(
            s.canvas.pixels.pixel(i % w, i / w),
            source.image.pixel(sx, sy)
        );
    }
}

/// The seam energy of the whole output from the labels alone: every edge between different
/// patches costs M of those patches (old seams are stored with exactly that cost).
fn seam_energy(s: &Synthesis) -> f64 {
    let mut total = 0.0;
    for i in 0..s.canvas.label.len() {
        for (j, horizontal) in [(s.canvas.right(i), true), (s.canvas.down(i), false)] {
            let Some(j) = j else { continue };
            if let (Some(a), Some(b)) = (s.patch_of(i), s.patch_of(j)) {
                total += f64::from(s.seam_cost(i, j, horizontal, a, b));
            }
        }
    }
    total
}

#[test]
fn the_cut_is_the_cheapest_labelling_including_old_seams() {
    // Old seams everywhere: a checkerboard of small patches first, then big patches over them.
    let exemplar = noise(12, 12, 3, 1);
    let options = Options {
        output_width: 20,
        output_height: 16,
        ..Options::default()
    };
    let mut s = Synthesis::new(&exemplar, options).unwrap();
    for (tx, ty) in [(0, 0), (8, 0), (0, 6), (9, 5), (5, 8), (14, 9), (10, 4)] {
        s.place(Patch::new(0, tx, ty), &[], &[]).unwrap();
    }
    assert_pixels_match_labels(&s);
    let mut rng = Rng::new(4);
    for _ in 0..12 {
        let patch = Patch::new(0, rng.index(18) as i32 - 6, rng.index(14) as i32 - 6);
        let before = s.clone_state();
        let [outside_before, border_before, _] = seam_energy_by_footprint(&s, patch);
        let placed = s.place(patch, &[], &[]).unwrap();
        assert_pixels_match_labels(&s);
        // The cut value is the seam energy inside the patch after placement (old seams kept,
        // new seams made). Edges with one pixel under the patch keep their seam: that pixel is
        // held to its old patch (or was uncovered, and no patch shows both pixels).
        let after = seam_energy(&s);
        let [outside_after, border_after, inside_after] = seam_energy_by_footprint(&s, patch);
        assert!(
            (outside_after - outside_before).abs() < 1e-3
                && (border_after - border_before).abs() < 1e-3,
            "nothing outside the patch changes"
        );
        assert!(
            (inside_after - placed.cut_cost).abs() < 1e-3 * after.max(1.0),
            "cut {} vs energy {inside_after}",
            placed.cut_cost,
        );
        // And no labelling the cut could have chosen is cheaper: keeping everything old, or
        // flipping any single free pixel of the result.
        let mut keep = before.clone_state();
        keep.place_keeping_old(patch);
        assert!(after <= seam_energy(&keep) + 1e-3);
        for i in s.footprint(patch) {
            if let Some(flipped) = s.flip(&before, patch, i) {
                assert!(
                    after <= seam_energy(&flipped) + 1e-3,
                    "flipping pixel {i} would be cheaper"
                );
            }
        }
    }
}

/// Seam energy of the edges with zero, one and two pixels under `patch`.
fn seam_energy_by_footprint(s: &Synthesis, patch: Patch) -> [f64; 3] {
    let under: std::collections::HashSet<usize> = s.footprint(patch).into_iter().collect();
    let mut totals = [0.0; 3];
    for i in 0..s.canvas.label.len() {
        for (j, horizontal) in [(s.canvas.right(i), true), (s.canvas.down(i), false)] {
            let Some(j) = j else { continue };
            if let (Some(a), Some(b)) = (s.patch_of(i), s.patch_of(j)) {
                let pixels_under =
                    usize::from(under.contains(&i)) + usize::from(under.contains(&j));
                totals[pixels_under] += f64::from(s.seam_cost(i, j, horizontal, a, b));
            }
        }
    }
    totals
}

impl Synthesis {
    fn clone_state(&self) -> Synthesis {
        Synthesis {
            options: self.options.clone(),
            sources: self.sources.clone(),
            canvas: self.canvas.clone(),
            rng: self.rng.clone(),
            used: self.used.clone(),
            sigma: self.sigma,
            ssd: crate::solvers::fft_ssd::SsdSearch::new(),
            seam_features: self.seam_features.clone(),
            seam_feature_weight: self.seam_feature_weight,
            max_source_side: self.max_source_side,
            windows: self.windows.clone(),
            record_anatomy: self.record_anatomy,
            last_graph: self.last_graph.clone(),
            graph: Default::default(),
        }
    }

    /// `patch` placed taking only the pixels it must (uncovered ones).
    fn place_keeping_old(&mut self, patch: Patch) {
        let index = self.canvas.patches.len() as u32;
        self.canvas.patches.push(patch);
        for i in self.footprint(patch) {
            if self.canvas.label[i] == UNCOVERED {
                self.canvas.label[i] = index;
            }
        }
    }

    /// The labelling `self` reached from `before` by placing `patch`, with pixel `i` flipped to
    /// the other choice, if that flip is allowed (not a constrained pixel).
    fn flip(&self, before: &Synthesis, patch: Patch, i: usize) -> Option<Synthesis> {
        if before.canvas.label[i] == UNCOVERED {
            return None; // must take the new patch
        }
        let under: std::collections::HashSet<usize> = self.footprint(patch).into_iter().collect();
        let border = [
            self.canvas.right(i),
            self.canvas.down(i),
            self.left(i),
            self.up(i),
        ]
        .into_iter()
        .flatten()
        .any(|j| !under.contains(&j) && before.canvas.label[j] != UNCOVERED);
        if border {
            return None; // must keep the old texture
        }
        let mut flipped = self.clone_state();
        let new_label = (self.canvas.patches.len() - 1) as u32;
        flipped.canvas.label[i] = if self.canvas.label[i] == new_label {
            before.canvas.label[i]
        } else {
            new_label
        };
        Some(flipped)
    }
}

#[test]
fn a_surrounded_region_keeps_its_border() {
    let exemplar = sample("gravel_64");
    let mut session = Session::new(
        &exemplar,
        Options {
            output_width: 96,
            output_height: 96,
            refinement_patches: 0,
            ..Options::default()
        },
    )
    .unwrap();
    while !session.step().unwrap().covered {}
    let mut s = session.synthesis().clone_state();
    let before = s.canvas.label.clone();
    let patch = Patch::new(0, 16, 16);
    let placed = s.place(patch, &[48 * 96 + 48], &[]).unwrap();
    assert!(placed.pixels_taken >= 1);
    assert_eq!(
        s.canvas.label[48 * 96 + 48] as usize,
        placed.index,
        "the forced pixel takes the patch"
    );
    for i in s.footprint(patch) {
        let (x, y) = (i % 96, i / 96);
        if x == 16 || y == 16 || x == 79 || y == 79 {
            assert_eq!(
                s.canvas.label[i], before[i],
                "border pixel ({x}, {y}) keeps the old texture"
            );
        }
    }
}

fn run(exemplar: &Image, options: Options) -> (Session, Vec<super::Event>) {
    let mut session = Session::new(exemplar, options).unwrap();
    let mut events = Vec::new();
    loop {
        let event = session.step().unwrap();
        events.push(event);
        if event.done {
            return (session, events);
        }
    }
}

#[test]
fn every_placement_mode_covers_the_output_without_reusing_an_offset() {
    let exemplar = sample("tiles_64");
    for placement in [
        Placement::Random,
        Placement::EntirePatch,
        Placement::SubPatch,
    ] {
        let options = Options {
            output_width: 100,
            output_height: 90,
            placement,
            refinement_patches: 6,
            ..Options::default()
        };
        let (session, events) = run(&exemplar, options);
        let s = session.synthesis();
        assert!(s.canvas.is_covered(), "{placement:?}");
        assert!(s.canvas.label.iter().all(|&l| l != UNCOVERED));
        assert_pixels_match_labels(s);
        let unique: std::collections::HashSet<Patch> = s.canvas.patches.iter().copied().collect();
        assert_eq!(
            unique.len(),
            s.canvas.patches.len(),
            "{placement:?} reused an offset"
        );
        let covered_at = events.iter().position(|e| e.covered).unwrap();
        assert_eq!(
            events.len() - covered_at - 1,
            6,
            "six refinement patches after covering"
        );
        assert!(
            (seam_energy(s) - events.last().unwrap().total_seam_cost).abs()
                < 1e-2 * seam_energy(s).max(1.0)
        );
    }
}

#[test]
fn same_seed_same_output() {
    let exemplar = sample("brick_64");
    let options = Options {
        output_width: 80,
        output_height: 80,
        refinement_patches: 4,
        ..Options::default()
    };
    let a = run(&exemplar, options.clone()).0.output().unwrap();
    let b = run(&exemplar, options.clone()).0.output().unwrap();
    let c = run(&exemplar, Options { seed: 9, ..options })
        .0
        .output()
        .unwrap();
    assert_eq!(a, b);
    assert_ne!(a, c);
}

/// The search looks only at the window the candidates' patches can reach: on outputs
/// much larger than that window, wrapping or not, before and after the output is covered, for
/// entire-patch and sub-patch matching, every candidate's cost is the direct area-normalised SSD
/// over the whole output.
#[test]
fn matching_costs_equal_a_direct_area_normalised_ssd() {
    use super::region::region_contains;
    let exemplar = noise(16, 12, 3, 3);
    for wrap in [false, true] {
        for placement in [Placement::EntirePatch, Placement::SubPatch] {
            for (ow, oh, steps) in [(30, 24, 2), (72, 56, 3), (40, 30, 40)] {
                let mut session = Session::new(
                    &exemplar,
                    Options {
                        output_width: ow,
                        output_height: oh,
                        placement,
                        tileable: wrap,
                        ..Options::default()
                    },
                )
                .unwrap();
                for _ in 0..steps {
                    session.step().unwrap();
                }
                let s = session.synthesis_mut();
                let region = s.error_region();
                let candidates = s.candidates(region);
                assert!(!candidates.is_empty());
                let scored = s.score(region, &candidates).unwrap();
                let (w, h) = (s.canvas.width, s.canvas.height);
                for c in &scored {
                    let (mut sum, mut area) = (0.0f64, 0.0f64);
                    for i in s.footprint(c.patch) {
                        let (x, y) = (i % w, i / w);
                        if s.canvas.label[i] == UNCOVERED
                            || (placement == Placement::SubPatch
                                && !region_contains(region, x, y, w, h, wrap))
                        {
                            continue;
                        }
                        let (sx, sy) = s.source_coords(c.patch, x, y).unwrap();
                        let a = s.canvas.pixels.pixel(x, y);
                        let b = s.sources[0].image.pixel(sx, sy);
                        sum += a
                            .iter()
                            .zip(b)
                            .map(|(x, y)| f64::from(x - y).powi(2))
                            .sum::<f64>();
                        area += 1.0;
                    }
                    if area < 1.0 {
                        assert!(c.cost.is_infinite(), "no overlap is no match");
                        continue;
                    }
                    let direct = (sum / area) as f32;
                    assert!(
                        (c.cost - direct).abs() < 1e-3 * direct.max(1e-3),
                        "{ow}x{oh} wrap {wrap} {placement:?} {:?}: fft {} vs direct {direct}",
                        c.patch,
                        c.cost
                    );
                }
            }
        }
    }
}

#[test]
fn tileable_output_wraps_seams_and_blends_are_sound() {
    let exemplar = sample("sand_64");
    let options = Options {
        output_width: 96,
        output_height: 80,
        tileable: true,
        refinement_patches: 4,
        ..Options::default()
    };
    let (session, _) = run(&exemplar, options.clone());
    let s = session.synthesis();
    assert!(s.canvas.is_covered());
    assert_pixels_match_labels(s);
    // Every wrap edge is costed like any other: the stored cost equals M of its two patches.
    for y in 0..80 {
        let (i, j) = (y * 96 + 95, y * 96);
        let expected = match (s.patch_of(i), s.patch_of(j)) {
            (Some(a), Some(b)) => s.seam_cost(i, j, true, a, b),
            _ => 0.0,
        };
        assert!((s.canvas.h_seam[i] - expected).abs() < 1e-5);
    }
    for blend in [Blend::Feather, Blend::Spline] {
        let (blended, _) = run(
            &exemplar,
            Options {
                blend,
                ..options.clone()
            },
        );
        let out = blended.output().unwrap();
        assert!(out.data().iter().all(|v| v.is_finite()));
        let raw = &blended.synthesis().canvas.pixels;
        let diff: f32 = out
            .data()
            .iter()
            .zip(raw.data())
            .map(|(a, b)| (a - b).abs())
            .sum::<f32>()
            / raw.data().len() as f32;
        assert!(
            diff > 0.0 && diff < 0.05,
            "{blend:?} changes the image a little: {diff}"
        );
    }
}

#[test]
fn a_single_patch_splines_to_itself_and_transforms_add_sources() {
    let exemplar = noise(32, 32, 1, 8);
    let options = Options {
        output_width: 32,
        output_height: 32,
        blend: Blend::Spline,
        ..Options::default()
    };
    let mut s = Synthesis::new(&exemplar, options).unwrap();
    s.place(Patch::new(0, 0, 0), &[], &[]).unwrap();
    let splined = s.splined().unwrap();
    assert!(
        splined
            .data()
            .iter()
            .zip(exemplar.data())
            .all(|(a, b)| (a - b).abs() < 1e-4)
    );
    assert_eq!(s.feathered(), s.canvas.pixels);

    let transforms = Transforms {
        rotate: true,
        mirror: true,
        scales: [Some(0.75), None, None, None],
        perspective: false,
    };
    let options = Options {
        output_width: 64,
        output_height: 64,
        transforms,
        refinement_patches: 2,
        ..Options::default()
    };
    let (session, _) = run(&sample("ballast_64"), options);
    assert_eq!(session.synthesis().sources.len(), 7);
    assert_pixels_match_labels(session.synthesis());
    let perspective = Transforms {
        scales: [Some(0.5), Some(0.75), None, None],
        perspective: true,
        ..Transforms::default()
    };
    let options = Options {
        output_width: 96,
        output_height: 96,
        transforms: perspective,
        refinement_patches: 0,
        ..Options::default()
    };
    let (session, _) = run(&sample("ballast_64"), options);
    let s = session.synthesis();
    // Scales grow from top to bottom: the mean scale of the top rows is below that of the bottom.
    let mean_scale = |rows: std::ops::Range<usize>| {
        let v: Vec<f32> = rows
            .flat_map(|y| (0..96).map(move |x| y * 96 + x))
            .map(|i| s.sources[s.patch_of(i).unwrap().source as usize].scale)
            .collect();
        v.iter().sum::<f32>() / v.len() as f32
    };
    assert!(
        mean_scale(0..20) < mean_scale(76..96),
        "{} vs {}",
        mean_scale(0..20),
        mean_scale(76..96)
    );
}

/// Patches laid down one by one over an output they only partly cover yet: each overlaps covered
/// pixels and uncovered ones.
const PARTIAL_COVER: [(i32, i32); 8] = [
    (0, 0),
    (7, 2),
    (2, 8),
    (12, 5),
    (9, 11),
    (16, 0),
    (15, 12),
    (0, 14),
];

/// Stored seam energy of the edges with both pixels under `patch`: what the cut that placed it
/// decided. (An edge leaving the footprint keeps its old cost, or costs nothing when its inside
/// pixel was uncovered, since no patch then shows both of its pixels.)
fn stored_energy_under(s: &Synthesis, patch: Patch) -> f64 {
    let under: std::collections::HashSet<usize> = s.footprint(patch).into_iter().collect();
    let mut total = 0.0;
    for &i in &under {
        for (j, seams) in [
            (s.canvas.right(i), &s.canvas.h_seam),
            (s.canvas.down(i), &s.canvas.v_seam),
        ] {
            if j.is_some_and(|j| under.contains(&j)) {
                total += f64::from(seams[i]);
            }
        }
    }
    total
}

#[test]
fn while_the_output_is_being_covered_the_cut_equals_the_stored_seam_energy() {
    let exemplar = noise(12, 12, 3, 1);
    for gradient_cost in [false, true] {
        let options = Options {
            output_width: 26,
            output_height: 22,
            gradient_cost,
            ..Options::default()
        };
        let mut s = Synthesis::new(&exemplar, options).unwrap();
        for (tx, ty) in PARTIAL_COVER {
            let patch = Patch::new(0, tx, ty);
            let placed = s.place(patch, &[], &[]).unwrap();
            assert_pixels_match_labels(&s);
            let stored = stored_energy_under(&s, patch);
            assert!(
                (placed.cut_cost - stored).abs() < 1e-4 * stored.max(1.0),
                "M' {gradient_cost}, patch at ({tx}, {ty}): cut {} vs stored seam energy {stored}",
                placed.cut_cost
            );
        }
        assert!(!s.canvas.is_covered(), "the test is about a partial cover");
    }
}

#[test]
fn the_cut_is_not_biased_by_the_new_patch_brightness() {
    // One texture, dark and bright: every colour difference between patches is the same, only
    // the distance to the black of uncovered output pixels differs. Values are multiples of
    // 2^-9, so both copies are exact and their costs equal bit for bit.
    let mut rng = Rng::new(3);
    let dark = Image::from_fn(12, 12, 3, |_, _, _| rng.index(256) as f32 / 512.0).unwrap();
    let bright = Image::from_vec(12, 12, 3, dark.data().iter().map(|v| v + 0.5).collect()).unwrap();
    let options = Options {
        output_width: 26,
        output_height: 22,
        ..Options::default()
    };
    let mut a = Synthesis::new(&dark, options.clone()).unwrap();
    let mut b = Synthesis::new(&bright, options).unwrap();
    let (mut taken_dark, mut taken_bright) = (0, 0);
    for (tx, ty) in PARTIAL_COVER {
        let patch = Patch::new(0, tx, ty);
        let (pa, pb) = (
            a.place(patch, &[], &[]).unwrap(),
            b.place(patch, &[], &[]).unwrap(),
        );
        taken_dark += pa.pixels_taken;
        taken_bright += pb.pixels_taken;
        let differing = a
            .canvas
            .label
            .iter()
            .zip(&b.canvas.label)
            .filter(|(x, y)| x != y)
            .count();
        assert!(
            differing == 0 && pa.cut_cost == pb.cut_cost,
            "patch at ({tx}, {ty}): {differing} pixels labelled differently; the bright patch \
             took {} pixels, the dark one {} (so far {taken_bright} vs {taken_dark}); cut {} vs {}",
            pb.pixels_taken,
            pa.pixels_taken,
            pb.cut_cost,
            pa.cut_cost
        );
    }
}

/// The feature-mismatch seam term adds its weight per pixel where exactly one patch shows a
/// feature, and nothing where they agree or one patch does not reach.
#[test]
fn the_seam_pays_for_features_the_patches_do_not_share() {
    let ex = Image::from_fn(16, 16, 3, |x, y, c| ((x * 3 + y * 5 + c) % 7) as f32 / 7.0).unwrap();
    let options = Options {
        output_width: 24,
        output_height: 24,
        ..Options::default()
    };
    let mut s = Synthesis::new(&ex, options).unwrap();
    let (a, b) = (Patch::new(0, 0, 0), Patch::new(0, 1, 0));
    let plain = s.seam_cost(5 * 24 + 5, 5 * 24 + 6, true, a, b);
    // A vertical curve at source column 5: patch a shows it at output x = 5, patch b at x = 6.
    s.seam_features = vec![(0..256).map(|i| i % 16 == 5).collect()];
    s.seam_feature_weight = 2.0;
    let with = s.seam_cost(5 * 24 + 5, 5 * 24 + 6, true, a, b);
    assert!((with - plain - 4.0).abs() < 1e-5, "{plain} {with}");
    // Both patches agree there (no feature at output x = 9, 10 in either).
    let far = s.seam_cost(5 * 24 + 9, 5 * 24 + 10, true, a, b);
    s.seam_feature_weight = 0.0;
    assert_eq!(far, s.seam_cost(5 * 24 + 9, 5 * 24 + 10, true, a, b));
    // Patch b does not reach output x = 0: no mismatch can be seen there.
    s.seam_feature_weight = 2.0;
    assert_eq!(s.feature_at(b, 5 * 24), None);
}

/// The synthesis without its per-pixel shortcut ([`Synthesis::cell_term`]): the seam graph then
/// costs every arc with `seam_cost` itself.
struct EdgeByEdge<'a>(&'a Synthesis);

impl SeamGrid for EdgeByEdge<'_> {
    type Label = Patch;
    const AXES: usize = 2;
    fn next(&self, i: usize, axis: usize) -> Option<usize> {
        SeamGrid::next(self.0, i, axis)
    }
    fn prev(&self, i: usize, axis: usize) -> Option<usize> {
        SeamGrid::prev(self.0, i, axis)
    }
    fn label_of(&self, i: usize) -> Option<Patch> {
        self.0.label_of(i)
    }
    fn old_seam(&self, s: usize, axis: usize) -> f32 {
        self.0.old_seam(s, axis)
    }
    fn seam_cost(&self, s: usize, t: usize, axis: usize, a: Patch, b: Patch) -> f32 {
        SeamGrid::seam_cost(self.0, s, t, axis, a, b)
    }
}

#[test]
fn per_pixel_terms_give_the_seam_graph_of_edge_by_edge_costs_to_the_bit() {
    let bits = |g: &SeamGraph| {
        let edges: Vec<_> = g
            .edges
            .iter()
            .map(|&(a, b, c)| (a, b, c.to_bits()))
            .collect();
        let terminals: Vec<_> = g
            .terminals
            .iter()
            .map(|&(n, a, b)| (n, a.to_bits(), b.to_bits()))
            .collect();
        (g.nodes, g.cells.clone(), edges, terminals, g.seams.clone())
    };
    for (wrap, gradient_cost) in [(false, false), (true, false), (false, true)] {
        let exemplar = noise(16, 16, 3, 3);
        let options = Options {
            output_width: 40,
            output_height: 32,
            tileable: wrap,
            gradient_cost,
            ..Options::default()
        };
        let mut s = Synthesis::new(&exemplar, options).unwrap();
        let mut rng = Rng::new(7);
        let mut seam_nodes = 0;
        // Placements over an empty, a partly covered and a covered output, old seams included.
        for _ in 0..40 {
            let patch = Patch::new(0, rng.index(44) as i32 - 4, rng.index(36) as i32 - 4);
            let some = s.canvas.label.iter().position(|&l| l != UNCOVERED);
            if let Some(i) = some {
                let a = s.patch_of(i).unwrap();
                assert_eq!(s.cell_term(i, a, patch).is_some(), !gradient_cost);
            }
            let fast = s.seam_graph(&s, patch, &[], &[]);
            let slow = s.seam_graph(&EdgeByEdge(&s), patch, &[], &[]);
            assert_eq!(bits(&fast), bits(&slow));
            seam_nodes += fast.seams.len();
            s.place(patch, &[], &[]).unwrap();
        }
        assert_eq!(s.canvas.covered, 40 * 32, "the output ends covered");
        assert!(seam_nodes > 0, "old seams were crossed");
    }
}
