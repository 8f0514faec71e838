//! Feature-guided synthesis (Wu & Yu 2004) against plain graph-cut textures, 256x256 from the
//! 128x128 samples: `cargo run --profile explore --example feature_compare [SAMPLES...]`
//! (default: the six structured samples and the rest of the shared set). Prints per sample and
//! method: time, coherence, completeness, flat fraction and the broken-feature count (curve
//! ends per 1000 curve pixels above the exemplar's; lower is better). `WRITE=dir` writes the
//! outputs; `SEEDS=1,2,3` averages over seeds; `WARP=0` turns the alignment off; `PATCH=48` (default 64);
//! `PLACEMENT=scan` (default graphcut); `SEAMW=0` (the seam's feature-mismatch weight, default 1);
//! `TOL`, `FW`, `CANDIDATES` as the options of the same names; `KINDS=1` prints the warp kinds.
//! `carried`: the same count on the carried maps instead of maps detected on the outputs (each
//! output pixel carries the exemplar's curve at the pixel it shows, as the synthesised feature
//! map does), so it counts curves ended by seams and nothing a detector finds in the pixels
//! (on planks, detected grain specks outnumber the cut board edges).

use std::time::Instant;
use texsynth::core::{Image, decode, encode_png};
use texsynth::methods::features::broken::{broken_features, carried_broken};
use texsynth::methods::features::carried::carried_mask;
use texsynth::methods::features::{
    DetectOptions, FeatureOptions, FeaturePlacement, FeatureSynthesis,
};
use texsynth::methods::graphcut::{Options, Session};
use texsynth::methods::quality::quality;

fn load(name: &str) -> Image {
    let path = format!("{}/www/samples/{name}.png", env!("CARGO_MANIFEST_DIR"));
    decode(&std::fs::read(path).expect("sample")).expect("decodes")
}

fn main() {
    let mut names: Vec<String> = std::env::args().skip(1).collect();
    if names.is_empty() {
        names = [
            "squares", "planks", "carpet", "brick", "tiles", "paving", "ballast", "dirt", "grass",
            "gravel", "jungle", "potatoes", "rock", "roof", "sand", "stone",
        ]
        .iter()
        .map(|n| format!("{n}_128"))
        .collect();
    }
    let seeds: Vec<u64> = std::env::var("SEEDS").map_or(vec![1], |v| {
        v.split(',').map(|s| s.parse().expect("seed")).collect()
    });
    let warp = std::env::var("WARP").map_or(true, |v| v != "0");
    let patch = std::env::var("PATCH").map_or(64, |v| v.parse().expect("patch"));
    let detect = DetectOptions::default();
    println!("sample\tmethod\tms\tcoherence\tcompleteness\tflat\tbroken\tcarried");
    let mut wins = 0;
    for name in &names {
        let exemplar = load(name);
        let own = texsynth::methods::features::detect(&exemplar, detect).expect("detect");
        let mut rows = [[0.0f64; 6]; 2];
        for &seed in &seeds {
            let start = Instant::now();
            let out_f = {
                let mut f = FeatureSynthesis::new(
                    &exemplar,
                    None,
                    FeatureOptions {
                        seed,
                        warp,
                        patch_size: Some(patch),
                        placement: std::env::var("PLACEMENT").map_or(
                            FeaturePlacement::Graphcut,
                            |v| {
                                FeaturePlacement::from_name(&v)
                                    .expect("placement: graphcut or scan")
                            },
                        ),
                        seam_feature_weight: std::env::var("SEAMW")
                            .map_or(1.0, |v| v.parse().expect("seam weight")),
                        tolerance: std::env::var("TOL")
                            .map_or(0.1, |v| v.parse().expect("tolerance")),
                        feature_candidates: std::env::var("CANDIDATES")
                            .ok()
                            .map(|v| v.parse().expect("candidates")),
                        feature_weight: std::env::var("FW")
                            .map_or(0.5, |v| v.parse().expect("weight")),
                        ..FeatureOptions::default()
                    },
                )
                .expect("features");
                let mut kinds = std::collections::BTreeMap::new();
                loop {
                    let e = f.step().expect("step");
                    *kinds.entry(format!("{:?}", e.warp)).or_insert(0) += 1;
                    if e.done {
                        break;
                    }
                }
                if std::env::var("KINDS").is_ok() {
                    eprintln!("{name} seed {seed}: {kinds:?}");
                }
                (f.image().clone(), f.carried_broken())
            };
            let (out_f, carried_f) = out_f;
            let t_f = start.elapsed().as_secs_f64() * 1e3;
            let start = Instant::now();
            let mut g = Session::new(
                &exemplar,
                Options {
                    seed,
                    ..Options::default()
                },
            )
            .expect("graphcut");
            while !g.step().expect("step").done {}
            let t_g = start.elapsed().as_secs_f64() * 1e3;
            let out_g = g.output().expect("output");
            let mask_g = carried_mask(g.synthesis(), &[&own.mask]);
            let carried_g = carried_broken(
                &mask_g,
                (out_g.width(), out_g.height()),
                &own.mask,
                (own.width, own.height),
            );
            for (row, (out, t, carried)) in rows
                .iter_mut()
                .zip([(&out_f, t_f, carried_f), (&out_g, t_g, carried_g)])
            {
                let q = quality(&exemplar, out).expect("quality");
                let b = broken_features(&exemplar, out, detect).expect("broken");
                for (acc, v) in
                    row.iter_mut()
                        .zip([t, q.coherence, q.completeness, q.flat, b, carried])
                {
                    *acc += v / seeds.len() as f64;
                }
            }
            if let Ok(dir) = std::env::var("WRITE") {
                std::fs::write(
                    format!("{dir}/{name}-features-{seed}.png"),
                    encode_png(&out_f).expect("png"),
                )
                .expect("write");
                std::fs::write(
                    format!("{dir}/{name}-graphcut-{seed}.png"),
                    encode_png(&out_g).expect("png"),
                )
                .expect("write");
            }
        }
        for (method, r) in ["features", "graphcut"].iter().zip(&rows) {
            println!(
                "{name}\t{method}\t{:.0}\t{:.2e}\t{:.2e}\t{:.3}\t{:.1}\t{:.1}",
                r[0], r[1], r[2], r[3], r[4], r[5]
            );
        }
        if rows[0][4] < rows[1][4] {
            wins += 1;
        }
    }
    println!(
        "feature-guided has fewer broken features on {wins} of {}",
        names.len()
    );
}
