//! Tests of where the region a patch must cover sits while the output is being covered
//! (`Options::fill_region`, used by `Synthesis::error_region`).

use super::options::{Options, Placement};
use super::session::Session;
use crate::core::testing::noise;

/// While the output is being covered, the region to cover has the first uncovered pixel a
/// quarter of its side in, for both matchings (where the output's border allows), and at its
/// centre when the caller sets the region's side (the paper's centred square).
#[test]
fn the_covering_region_has_the_first_uncovered_pixel_a_quarter_in() {
    const SIDE: usize = 160;
    let exemplar = noise(48, 48, 3, 5);
    for (placement, error_region, lead) in [
        (Placement::EntirePatch, 0, 0.25),
        (Placement::SubPatch, 0, 0.25),
        (Placement::SubPatch, 12, 0.5),
        (Placement::EntirePatch, 12, 0.5),
    ] {
        let mut session = Session::new(
            &exemplar,
            Options {
                output_width: SIDE,
                output_height: SIDE,
                placement,
                error_region,
                ..Options::default()
            },
        )
        .unwrap();
        let mut checked = 0;
        for _ in 0..40 {
            let s = session.synthesis_mut();
            if s.canvas.is_covered() {
                break;
            }
            let region = s.error_region();
            let first = s.canvas.first_uncovered().unwrap();
            let (x, y) = (first % SIDE, first / SIDE);
            let want = (region.width as f32 * lead) as usize;
            assert!(
                region.x <= x && x < region.x + region.width,
                "{placement:?}"
            );
            assert!(
                region.y <= y && y < region.y + region.height,
                "{placement:?}"
            );
            // Away from the border the lead is exact.
            if x >= want
                && y >= want
                && x + region.width <= SIDE + want
                && y + region.height <= SIDE + want
            {
                assert_eq!(
                    (x - region.x, y - region.y),
                    (want, want),
                    "{placement:?} {error_region}"
                );
                checked += 1;
            }
            session.step().unwrap();
        }
        assert!(
            checked > 0,
            "{placement:?} {error_region}: no region away from the border"
        );
    }
}
