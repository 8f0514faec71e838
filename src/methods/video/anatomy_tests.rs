//! The placement anatomy of video textures: recording it changes no output, the cost slice is
//! the direct area-normalised SSD of eq. 4 (or eq. 2) at the drawn time shift, and the graph slice agrees
//! with what the placement took.

use super::canvas::UNCOVERED;
use super::options::{Mode, Options, Placement};
use super::placement::region_around;
use super::procedural::waves;
use super::session::Session;
use crate::methods::graphcut::anatomy::NodeKind;

fn session(placement: Placement) -> Session {
    let options = Options {
        mode: Mode::Extend,
        output_width: Some(28),
        output_height: Some(24),
        output_frames: Some(12),
        fixed_frames: Some(0),
        placement,
        refinement_patches: 4,
        seed: 3,
        ..Options::default()
    };
    Session::new(waves(14, 12, 8, 5).unwrap(), options).unwrap()
}

#[test]
fn recording_the_anatomy_changes_no_output() {
    for placement in [Placement::Random, Placement::EntirePatch, Placement::SubPatch] {
        let mut plain = session(placement);
        let mut watched = session(placement);
        watched.set_anatomy(true);
        while !plain.is_done() {
            assert_eq!(plain.step().unwrap(), watched.step().unwrap());
        }
        assert!(watched.is_done());
        assert_eq!(
            plain.synthesis().canvas.pixels,
            watched.synthesis().canvas.pixels
        );
    }
}

/// While the output is being covered, the session's error region is the box of a third of
/// the clip (here 5 x 4 x 3) around the first uncovered voxel: every candidate patch contains it,
/// so eq. 4's cost is the mean squared difference over its covered voxels.
#[test]
fn the_cost_slice_is_the_direct_ssd_at_the_drawn_time_shift() {
    check_cost_slices(Placement::SubPatch);
}

/// Entire-patch matching's cost (eq. 2) is the mean squared difference over every covered voxel
/// the whole clip overlaps at that offset, wherever it lies, not only in the error region.
#[test]
fn the_entire_patch_cost_is_the_direct_ssd_over_the_whole_overlap() {
    check_cost_slices(Placement::EntirePatch);
}

fn check_cost_slices(placement: Placement) {
    let mut s = session(placement);
    s.set_anatomy(true);
    s.step().unwrap();
    let source = s.synthesis().sources[0].volume.clone();
    let clip = (
        source.width() as i64,
        source.height() as i64,
        source.frames() as i64,
    );
    let (mut slices, mut checked) = (0, 0);
    while !s.synthesis().canvas.is_covered() {
        let canvas = &s.synthesis().canvas;
        let (pixels, label) = (canvas.pixels.clone(), canvas.label.clone());
        let size = canvas.size();
        let (w, h, _) = size;
        let first = s.synthesis().first_uncovered().expect("not covered");
        let region = region_around(canvas.coords(first), (5, 4, 3), size);
        let event = s.step().unwrap();
        let Some(slice) = s.placement_costs().cloned() else {
            continue;
        };
        slices += 1;
        let c = &slice.surface;
        assert!(!slice.temporal);
        let total: f32 = c.probability.iter().sum();
        assert!((total - 1.0).abs() < 1e-3, "probabilities sum to {total}");
        let (cx, cy) = c.chosen.expect("a patch was drawn");
        assert_eq!(
            (c.x + cx as i64, c.y + cy as i64, slice.tt),
            (
                i64::from(event.offset.0),
                i64::from(event.offset.1),
                event.offset.2
            ),
            "the marked cell is the placed offset (no fixed frames: canvas = output frames)"
        );
        // The voxels eq. 4 compares (the region), or eq. 2 (the whole output under the patch).
        let (origin, extent) = if placement == Placement::EntirePatch {
            ((0, 0, 0), size)
        } else {
            (region.origin, region.size)
        };
        let (ox, oy, ot) = origin;
        for gy in (0..c.height).step_by(2) {
            for gx in (0..c.width).step_by(2) {
                let cost = c.cost[gy * c.width + gx];
                if !cost.is_finite() {
                    continue;
                }
                let (tx, ty, tt) = (c.x + gx as i64, c.y + gy as i64, i64::from(slice.tt));
                let (mut ssd, mut n) = (0.0f64, 0usize);
                for f in ot..ot + extent.2 {
                    for y in oy..oy + extent.1 {
                        for x in ox..ox + extent.0 {
                            let i = (f * h + y) * w + x;
                            let (u, v, t) = (x as i64 - tx, y as i64 - ty, f as i64 - tt);
                            let inside = (0..clip.0).contains(&u)
                                && (0..clip.1).contains(&v)
                                && (0..clip.2).contains(&t);
                            if label[i] == UNCOVERED || !inside {
                                continue;
                            }
                            let k = source.index(u as usize, v as usize, t as usize);
                            ssd += pixels
                                .voxel(i)
                                .iter()
                                .zip(source.voxel(k))
                                .map(|(a, b)| f64::from(a - b).powi(2))
                                .sum::<f64>();
                            n += 1;
                        }
                    }
                }
                let direct = (ssd / n as f64) as f32;
                assert!(
                    (cost - direct).abs() <= 1e-3 * direct.max(1e-2),
                    "offset ({tx}, {ty}, {tt}): surface {cost}, direct {direct}"
                );
                checked += 1;
            }
        }
    }
    assert!(slices >= 3, "{slices} matched placements recorded");
    assert!(checked > 20, "{checked} offsets checked");
}

/// The graph slice is the frame of the box with the most nodes, and agrees with the canvas
/// after the placement: taken pixels show the new patch, uncovered ones all took it, pixels held
/// to the old output kept it.
#[test]
fn the_graph_slice_is_the_fullest_frame_and_matches_the_placement() {
    let mut s = session(Placement::Random);
    s.set_anatomy(true);
    let mut seen_free = 0;
    while !s.is_done() {
        let before = s.synthesis().canvas.label.clone();
        let Some(patch) = s.step().unwrap().patch else {
            continue;
        };
        let g = s.placement_graph().expect("recorded").clone();
        let canvas = &s.synthesis().canvas;
        let (w, h, _) = canvas.size();
        assert!((g.first_frame..g.first_frame + g.frames).contains(&g.t));
        let view = &g.view;
        // Graph nodes per frame of the box: the voxels covered before the placement.
        let nodes = |f: usize| {
            (0..view.height)
                .flat_map(|v| (0..view.width).map(move |u| (u, v)))
                .filter(|&(u, v)| {
                    let i = (f * h + view.y as usize + v) * w + view.x as usize + u;
                    before[i] != UNCOVERED
                })
                .count()
        };
        let fullest = (g.first_frame..g.first_frame + g.frames)
            .map(nodes)
            .max()
            .unwrap();
        assert_eq!(nodes(g.t), fullest, "frame {} of the box", g.t);
        let in_graph = |k: usize| view.kind[k] != NodeKind::Outside as u8;
        let count = view
            .kind
            .iter()
            .filter(|&&k| k >= NodeKind::Free as u8)
            .count();
        // Every voxel covered before the placement is a graph node (free or held to a side);
        // every uncovered one takes the new patch without a node.
        assert_eq!(count, nodes(g.t), "graph nodes in frame {}", g.t);
        for v in 0..view.height {
            for u in 0..view.width {
                let k = v * view.width + u;
                let i = (g.t * h + view.y as usize + v) * w + view.x as usize + u;
                let shows_new = canvas.label[i] == patch as u32;
                assert!(in_graph(k), "the box lies inside the output");
                assert_eq!(view.taken[k] == 1, shows_new, "pixel ({u}, {v})");
                match view.kind[k] {
                    k if k == NodeKind::New as u8 => assert!(shows_new),
                    k if k == NodeKind::KeepOld as u8 => assert!(!shows_new),
                    k if k == NodeKind::Free as u8 => seen_free += 1,
                    _ => {}
                }
            }
        }
    }
    assert!(seen_free > 100, "{seen_free} free nodes seen");
}

/// 7.C matching draws low-SSD offsets (eq. 3): over every matched placement, the drawn offset's
/// cost lies in the cheapest tenth of the finite costs of its slice far more often than a
/// uniform draw would put it there, and on average well below the slice's median.
#[test]
fn matching_draws_offsets_of_low_ssd() {
    for placement in [Placement::EntirePatch, Placement::SubPatch] {
        draws_offsets_of_low_ssd(placement);
    }
}

fn draws_offsets_of_low_ssd(placement: Placement) {
    let mut s = session(placement);
    s.set_anatomy(true);
    let (mut matched, mut cheapest_tenth, mut below_median) = (0, 0, 0);
    while !s.is_done() {
        let placed = s.step().unwrap().patch.is_some();
        let Some(slice) = s.placement_costs().filter(|_| placed) else {
            continue;
        };
        let surface = &slice.surface;
        let (cx, cy) = surface.chosen.expect("the drawn offset is on its slice");
        let drawn = surface.cost[cy * surface.width + cx];
        let mut finite: Vec<f32> = surface.cost.iter().copied().filter(|c| c.is_finite()).collect();
        if finite.len() < 10 {
            continue;
        }
        finite.sort_by(f32::total_cmp);
        matched += 1;
        cheapest_tenth += usize::from(drawn <= finite[finite.len() / 10]);
        below_median += usize::from(drawn <= finite[finite.len() / 2]);
    }
    assert!(matched >= 3, "{placement:?}: {matched} matched placements");
    // A uniform draw lands in the cheapest tenth one time in ten.
    assert!(
        cheapest_tenth * 2 >= matched,
        "{placement:?}: {cheapest_tenth} of {matched} draws in the cheapest tenth"
    );
    assert_eq!(below_median, matched, "{placement:?}: every draw below its slice's median");
}

#[test]
fn constrained_frames_are_matched_under_matching() {
    // Frames larger than the input: 7.D's first k frames take several patches, the first at
    // the origin. Under matching the others are drawn by eq. 3 from their SSD, as 7.C's are.
    for placement in [Placement::EntirePatch, Placement::SubPatch] {
        constrained_frames_are_matched(placement);
    }
}

fn constrained_frames_are_matched(placement: Placement) {
    let options = Options {
        mode: Mode::Extend,
        output_width: Some(28),
        output_height: Some(24),
        output_frames: Some(12),
        fixed_frames: Some(3),
        placement,
        seed: 3,
        ..Options::default()
    };
    let mut s = Session::new(waves(14, 12, 8, 5).unwrap(), options).unwrap();
    s.set_anatomy(true);
    s.step().unwrap(); // the origin: the input's own first frames
    for step in 1..4 {
        s.step().unwrap();
        let slice = s
            .placement_costs()
            .unwrap_or_else(|| panic!("{placement:?} step {step}: a matched placement has its costs"));
        let surface = &slice.surface;
        let (cx, cy) = surface.chosen.expect("the drawn offset is on its slice");
        let drawn = surface.cost[cy * surface.width + cx];
        let mut finite: Vec<f32> = surface.cost.iter().copied().filter(|c| c.is_finite()).collect();
        finite.sort_by(f32::total_cmp);
        assert!(finite.len() >= 10, "step {step}: {} finite costs", finite.len());
        assert!(
            drawn <= finite[finite.len() / 2],
            "{placement:?} step {step}: the draw lies below its slice's median"
        );
    }
}
