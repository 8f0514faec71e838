//! Tests of the bound on the part of a source one placement uses (`source_window.rs`): large
//! photos are searched through bounded windows, small exemplars are unchanged by it, and a photo
//! used whole that no search could handle is refused before any step.

use super::options::{Options, Placement};
use super::session::Session;
use super::synthesis::Synthesis;
use super::tests::assert_pixels_match_labels;
use crate::core::Image;
use crate::core::testing::sample;

/// A photo larger than the bound (`source_window.rs`) is accepted by every placement, and each
/// placement reads only a bounded window of it, drawn afresh: the patch, the candidates and the
/// FFT search are those of a `MAX_SOURCE_SIDE` exemplar, while the windows move over the photo.
#[test]
fn a_large_exemplar_is_searched_through_bounded_windows() {
    use super::region::SearchWindow;
    use super::source_window::MAX_SOURCE_SIDE;
    use crate::solvers::fft_ssd::transform_size;
    let photo = Image::from_fn(1500, 1200, 3, |x, y, c| {
        (((x * 7 + y * 3 + c * 5) % 23) as f32 / 23.0 + ((x / 40 + y / 30) % 3) as f32) / 3.0
    })
    .unwrap();
    let bound = (MAX_SOURCE_SIDE, MAX_SOURCE_SIDE);
    for (placement, tileable) in [
        (Placement::EntirePatch, false),
        (Placement::SubPatch, false),
        (Placement::Random, false),
        (Placement::SubPatch, true),
    ] {
        let mut session = Session::new(
            &photo,
            Options {
                output_width: 96,
                output_height: 96,
                placement,
                tileable,
                refinement_patches: 3,
                ..Options::default()
            },
        )
        .unwrap();
        assert_eq!(session.synthesis().window_extent(0), bound);
        let mut steps = 0;
        loop {
            // What the step will search: the candidates of one window, and a bounded transform.
            let s = session.synthesis();
            let region = s.error_region();
            let extent = s.patch_extent(0);
            assert!(extent.0 <= MAX_SOURCE_SIDE && extent.1 <= MAX_SOURCE_SIDE);
            let window = SearchWindow::of(placement, region, extent, (96, 96), tileable);
            let (nx, ny) = transform_size((window.width, window.height), extent, window.boundary);
            assert!(
                nx <= 3 * MAX_SOURCE_SIDE && ny <= 3 * MAX_SOURCE_SIDE,
                "{nx}x{ny}"
            );
            let event = session.step().unwrap();
            steps += 1;
            let patch = event.patch.expect("a patch is placed");
            let (wx, wy) = (patch.window.0 as usize, patch.window.1 as usize);
            assert!(wx + extent.0 <= 1500 && wy + extent.1 <= 1200, "{patch:?}");
            assert_eq!((event.rect.2, event.rect.3), extent);
            if event.done {
                break;
            }
            assert!(steps < 50, "{placement:?} does not finish");
        }
        let s = session.synthesis();
        assert_pixels_match_labels(s);
        assert!(s.canvas.is_covered());
        let windows: std::collections::HashSet<(u32, u32)> =
            s.canvas.patches.iter().map(|p| p.window).collect();
        assert!(windows.len() > 1, "{placement:?}: the window never moved");
    }
}

/// An exemplar within the bound is its own window: the results are exactly those of the method
/// without the bound (every patch the whole exemplar), for every placement, wrapping or not.
#[test]
fn small_exemplars_are_unchanged_by_the_source_bound() {
    let exemplar = sample("tiles_64");
    for (placement, tileable) in [
        (Placement::EntirePatch, false),
        (Placement::SubPatch, false),
        (Placement::Random, false),
        (Placement::EntirePatch, true),
    ] {
        let run = |max_source_side: usize| {
            let mut session = Session::new(
                &exemplar,
                Options {
                    output_width: 96,
                    output_height: 80,
                    placement,
                    tileable,
                    refinement_patches: 6,
                    ..Options::default()
                },
            )
            .unwrap();
            session.synthesis_mut().max_source_side = max_source_side;
            while !session.step().unwrap().done {}
            let s = session.synthesis();
            assert!(s.canvas.patches.iter().all(|p| p.window == (0, 0)));
            (s.canvas.patches.clone(), session.output().unwrap())
        };
        assert_eq!(run(super::source_window::MAX_SOURCE_SIDE), run(usize::MAX));
    }
}

/// Used whole (no bound), a photo would need a transform larger than the FFT search allows; that
/// is still refused before any step, with a message saying what to do.
#[test]
fn an_exemplar_used_whole_that_is_too_large_to_search_is_refused() {
    let photo = Image::new(3000, 2000, 1).unwrap();
    let mut s = Synthesis::new(&photo, Options::default()).expect("bounded: accepted");
    assert!(s.check_search_size().is_ok());
    s.max_source_side = usize::MAX;
    let message = s.check_search_size().unwrap_err().to_string();
    assert!(
        message.contains("3000x2000") && message.contains("resized"),
        "{message}"
    );
}
