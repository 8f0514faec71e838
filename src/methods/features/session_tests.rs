//! Tests of the feature-guided session: whole runs, graph-cut placement, edited feature masks.

use super::*;

mod synthesis {
    use super::*;
    use crate::core::testing::sample;

    fn run(exemplar: &Image, options: FeatureOptions) -> (Image, Vec<FeatureEvent>, Vec<bool>) {
        let mut s = FeatureSynthesis::new(exemplar, None, options).unwrap();
        let mut events = Vec::new();
        loop {
            let e = s.step().unwrap();
            events.push(e);
            if e.done {
                return (s.image().clone(), events, s.feature_mask().to_vec());
            }
        }
    }

    #[test]
    fn it_grows_texture_and_feature_map_together() {
        let ex = sample("tiles_64");
        let options = FeatureOptions {
            output_width: 100,
            output_height: 90,
            patch_size: Some(32),
            placement: FeaturePlacement::Scan,
            ..FeatureOptions::default()
        };
        let (img, events, map) = run(&ex, options.clone());
        assert_eq!((img.width(), img.height()), (100, 90));
        let last = events.last().unwrap();
        assert_eq!(last.patches, events.len());
        assert!(
            events
                .iter()
                .skip(1)
                .any(|e| e.context_features > 0 && e.correspondences > 0)
        );
        assert!(events.iter().all(|e| !e.colour_only));
        assert!(events.iter().any(|e| e.warp == WarpKind::Spline));
        assert!(
            map.iter().filter(|&&m| m).count() > 200,
            "the feature map grew"
        );
        // Every pixel is made (no black left), and the run repeats exactly.
        assert!(img.data().chunks(3).all(|p| p.iter().sum::<f32>() > 0.0));
        assert_eq!(run(&ex, options).0, img);
    }

    #[test]
    fn the_default_patch_fits_an_exemplar_smaller_than_it() {
        // 40x40 and a 100x24 strip: without a patchSize they run under both placements (as
        // graph cut does); a patchSize the caller chose that does not fit is still refused, and
        // an exemplar under the smallest patch is refused by its size.
        let gravel = sample("gravel_64");
        for (w, h) in [(40, 40), (64, 24)] {
            let ex = gravel.crop(0, 0, w, h).unwrap();
            for placement in [FeaturePlacement::Graphcut, FeaturePlacement::Scan] {
                let options = FeatureOptions {
                    output_width: 72,
                    output_height: 64,
                    placement,
                    ..FeatureOptions::default()
                };
                let (img, events, _) = run(&ex, options);
                assert_eq!((img.width(), img.height()), (72, 64));
                assert!(events.last().unwrap().done, "{w}x{h} {placement:?}");
                assert!(img.data().chunks(3).all(|p| p.iter().sum::<f32>() > 0.0));
            }
        }
        let ex = gravel.crop(0, 0, 40, 40).unwrap();
        let chosen = FeatureOptions {
            patch_size: Some(48),
            ..FeatureOptions::default()
        };
        let msg = FeatureSynthesis::new(&ex, None, chosen)
            .err()
            .unwrap()
            .to_string();
        assert!(
            msg.contains("patchSize: 48 is larger than the 40x40"),
            "{msg}"
        );
        let tiny = gravel.crop(0, 0, 15, 30).unwrap();
        let msg = FeatureSynthesis::new(&tiny, None, FeatureOptions::default())
            .err()
            .unwrap()
            .to_string();
        assert!(
            msg.contains("exemplar size 15x30") && msg.contains("16x16"),
            "{msg}"
        );
    }

    #[test]
    fn without_features_it_matches_colour_only_and_says_so() {
        for placement in [FeaturePlacement::Scan, FeaturePlacement::Graphcut] {
            colour_only(placement);
        }
    }

    fn colour_only(placement: FeaturePlacement) {
        // A gentle, smooth gradient has no edges or ridges above the floor.
        let ex = Image::from_fn(48, 48, 3, |x, y, c| 0.4 + (x + y + c) as f32 / 4000.0).unwrap();
        let options = FeatureOptions {
            output_width: 64,
            output_height: 64,
            patch_size: Some(16),
            placement,
            ..FeatureOptions::default()
        };
        let (_, events, map) = run(&ex, options);
        assert!(
            events
                .iter()
                .skip(1)
                .all(|e| e.colour_only
                    && e.warp
                        == match placement {
                            FeaturePlacement::Scan => WarpKind::None,
                            FeaturePlacement::Graphcut => WarpKind::Unavailable,
                        })
        );
        assert!(map.iter().all(|&m| !m));
    }

    #[test]
    fn bad_options_are_named() {
        let ex = sample("tiles_64");
        let err = |o: FeatureOptions| {
            FeatureSynthesis::new(&ex, None, o)
                .err()
                .unwrap()
                .to_string()
        };
        assert!(
            err(FeatureOptions {
                patch_size: Some(8),
                ..FeatureOptions::default()
            })
            .contains("patchSize")
        );
        assert!(
            err(FeatureOptions {
                patch_size: Some(100),
                ..FeatureOptions::default()
            })
            .contains("larger than the 64x64")
        );
        assert!(
            err(FeatureOptions {
                patch_size: Some(32),
                feature_weight: f32::NAN,
                ..FeatureOptions::default()
            })
            .contains("featureWeight")
        );
        assert!(
            err(FeatureOptions {
                patch_size: Some(32),
                overlap: Some(20),
                ..FeatureOptions::default()
            })
            .contains("overlap")
        );
        let map = detect(&sample("tiles_128"), DetectOptions::default()).unwrap();
        let msg = FeatureSynthesis::new(
            &ex,
            Some(map),
            FeatureOptions {
                patch_size: Some(32),
                ..FeatureOptions::default()
            },
        )
        .err()
        .unwrap()
        .to_string();
        assert!(
            msg.contains("feature map") && msg.contains("64x64"),
            "{msg}"
        );
    }
}
mod graphcut_placement {
    use super::*;
    use crate::core::testing::sample;

    fn run(options: FeatureOptions) -> (Image, Vec<FeatureEvent>, Vec<bool>) {
        let ex = sample("tiles_64");
        let mut s = FeatureSynthesis::new(&ex, None, options).unwrap();
        let mut events = Vec::new();
        while !s.is_done() {
            events.push(s.step().unwrap());
        }
        (s.image().clone(), events, s.feature_mask().to_vec())
    }

    /// The synthesised feature map, updated over each placement's patch only, equals the map
    /// made afresh from the whole canvas after every step (covering and refinement alike).
    #[test]
    fn the_feature_map_kept_per_patch_equals_the_whole_canvas_map() {
        let options = FeatureOptions {
            output_width: 150,
            output_height: 110,
            patch_size: Some(32),
            ..FeatureOptions::default()
        };
        let mut s = FeatureSynthesis::new(&sample("tiles_64"), None, options).unwrap();
        let mut covered_steps = 0;
        while !s.is_done() {
            s.step().unwrap();
            let g = s.graphcut.as_ref().expect("graph-cut placement");
            let synthesis = g.session.synthesis();
            covered_steps += usize::from(synthesis.canvas.is_covered());
            let (mask, angle) =
                crate::methods::features::carried::canvas_features(synthesis, &g.features);
            assert_eq!(s.feature_mask(), &mask[..]);
            assert_eq!(s.feature_angles(), &angle[..]);
        }
        assert!(covered_steps > 1, "refinement steps were checked too");
    }

    #[test]
    fn graph_cut_placement_grows_texture_and_feature_map_with_the_feature_cost() {
        let options = FeatureOptions {
            output_width: 100,
            output_height: 90,
            patch_size: Some(32),
            ..FeatureOptions::default()
        };
        assert_eq!(options.placement, FeaturePlacement::Graphcut);
        let (img, events, map) = run(options.clone());
        assert_eq!((img.width(), img.height()), (100, 90));
        assert!(events.last().unwrap().done);
        // After the first patch, choices see context features and pay a feature cost.
        assert!(events.iter().skip(1).all(|e| !e.colour_only));
        assert!(
            events
                .iter()
                .skip(1)
                .any(|e| e.context_features > 0 && e.feature_cost > 0.0)
        );
        // The warp option is on by default, and graph-cut placement says it cannot warp.
        assert!(options.warp);
        assert!(events.iter().all(|e| e.warp == WarpKind::Unavailable));
        assert!(map.iter().filter(|&&m| m).count() > 200);
        assert!(img.data().chunks(3).all(|p| p.iter().sum::<f32>() > 0.0));
        assert_eq!(run(options.clone()).0, img, "the run repeats exactly");
        // The feature terms change the result: off, it is another synthesis.
        let plain = run(FeatureOptions {
            feature_weight: 0.0,
            seam_feature_weight: 0.0,
            ..options
        });
        assert_ne!(plain.0, img);
    }
}

mod masks {
    use super::*;
    use crate::core::testing::sample;

    #[test]
    fn a_map_rebuilt_from_its_mask_gives_the_same_synthesis() {
        let ex = sample("tiles_64");
        let mut map = detect(&ex, DetectOptions::default()).unwrap();
        map.paint(10.0, 10.0, 3.0, false);
        map.paint(40.0, 40.0, 1.0, true);
        let mut rebuilt = detect(&ex, DetectOptions::default()).unwrap();
        rebuilt.mask.clone_from(&map.mask);
        assert!(rebuilt == map);
        let options = FeatureOptions {
            output_width: 96,
            output_height: 96,
            patch_size: Some(32),
            placement: FeaturePlacement::Scan,
            ..FeatureOptions::default()
        };
        let run = |m: FeatureMap| {
            let mut s = FeatureSynthesis::new(&ex, Some(m), options.clone()).unwrap();
            while !s.step().unwrap().done {}
            s.image().clone()
        };
        assert!(run(map) == run(rebuilt));
    }
}
