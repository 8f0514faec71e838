//! Texture design (Shen et al. 2009) timings, native: `cargo run --release -p texsynth-bench --bin
//! design_bench` (the wasm figures come from `scripts/bench-design.mjs`). Prints
//! - layer-based design at 360x360 with patches of 32, 64 and 92 (Table 2), QTP against
//!   exhaustive search on the same layout, always taking the best match so both make the same
//!   choices when they find the same patch: time, pixel differences computed and total SSD;
//! - making a 256x256 and a 1024x1024 image tileable;
//! - one brush stroke (labelling and Poisson paste) on a 256x256 base.
//!
//! `DESIGN_SAMPLE` picks the layer texture (default tiles_128).

use std::time::Instant;
use texsynth::core::{Edge, Image, decode, encode_png, sample::resize_bilinear};
use texsynth::methods::design::layers::qtp::{Query, SearchCount, SearchTexture};
use texsynth::methods::design::layers::{
    Layer, LayerDesign, LayerOptions, LayerPlacement, LayerSearch,
};
use texsynth::methods::design::{
    BrushOptions, LocalDeformation, Stroke, TileableOptions, make_tileable,
};

fn load(name: &str) -> texsynth::core::Image {
    let path = format!("{}/www/samples/{name}.png", env!("CARGO_MANIFEST_DIR"));
    decode(&std::fs::read(path).expect("sample")).expect("decodes")
}

/// Sums over queries of (best SSD, pixel differences) for QTP and for the exhaustive search.
fn same_queries(texture: &Image, output: &Image, patch: usize) -> ((f64, usize), (f64, usize)) {
    let search = SearchTexture::new(texture, patch);
    let zone = (patch / 6).max(2);
    let c = output.channels();
    let (mut fast, mut exact) = ((0.0, SearchCount::default()), (0.0, SearchCount::default()));
    let step = patch - zone;
    for py in (0..=output.height() - patch).step_by(step).skip(1) {
        for px in (0..=output.width() - patch).step_by(step).skip(1) {
            let mut values = Vec::with_capacity(patch * patch * c);
            for y in 0..patch {
                for x in 0..patch {
                    values.extend_from_slice(output.pixel(px + x, py + y));
                }
            }
            let query = Query {
                size: patch,
                channels: c,
                mask: (0..patch * patch)
                    .map(|i| i % patch < zone || i / patch < zone)
                    .collect(),
                values,
            };
            let keep = std::env::var("KEEP").map_or(32, |k| k.parse().expect("keep"));
            fast.0 += f64::from(search.qtp(&query, keep, &mut fast.1)[0].0);
            exact.0 += f64::from(search.exhaustive(&query, &mut exact.1)[0].0);
        }
    }
    ((fast.0, fast.1.pixels), (exact.0, exact.1.pixels))
}

fn main() {
    let name = std::env::var("DESIGN_SAMPLE").unwrap_or_else(|_| "tiles_128".into());
    let texture = load(&name);
    println!("layer-based design, {name}, 360x360, best match, one layer:");
    println!("patch | search | time | pixel differences | total SSD");
    for patch in [32, 64, 92] {
        let mut figures = Vec::new();
        let mut output = texture.clone();
        for search in [LayerSearch::Qtp, LayerSearch::Exhaustive] {
            let layers = [Layer {
                texture: texture.clone(),
                deformations: vec![],
            }];
            let options = LayerOptions {
                patch_size: patch,
                search,
                placement: LayerPlacement::Best,
                keep: std::env::var("KEEP").map_or(32, |k| k.parse().expect("keep")),
                ..LayerOptions::default()
            };
            let start = Instant::now();
            let mut d = LayerDesign::new(&layers, &vec![0; 360 * 360], options).expect("design");
            let last = loop {
                let e = d.step().expect("step");
                if e.done {
                    break e;
                }
            };
            let t = start.elapsed().as_secs_f64();
            println!(
                "{patch} | {search:?} | {t:.3} s | {} | {:.2}",
                last.pixels_compared, last.total_ssd
            );
            figures.push((t, last.total_ssd));
            if let Ok(dir) = std::env::var("WRITE") {
                let png = encode_png(d.image()).expect("png");
                std::fs::write(format!("{dir}/layers-{name}-{patch}-{search:?}.png"), png)
                    .expect("write");
            }
            output = d.image().clone();
        }
        println!(
            "{patch} | QTP: {:.1}x faster, SSD {:+.1}% (each run follows its own choices)",
            figures[1].0 / figures[0].0,
            100.0 * (figures[0].1 / figures[1].1 - 1.0)
        );
        // The same queries for both: L-shaped zones cut from one finished output at every
        // patch position.
        let (fast, exact) = same_queries(&texture, &output, patch);
        println!(
            "{patch} | same queries: QTP's best SSD {:+.2}% against the exhaustive best, {:.1}x fewer pixel differences",
            100.0 * (fast.0 / exact.0 - 1.0),
            exact.1 as f64 / fast.1 as f64
        );
    }
    println!();
    for size in std::env::var("TILE_SIZES").map_or(vec![256, 1024], |v| {
        v.split(',').map(|s| s.parse().expect("size")).collect()
    }) {
        let image = resize_bilinear(&texture, size, size, Edge::Clamp).expect("resize");
        let start = Instant::now();
        let overlap = std::env::var("OVERLAP")
            .ok()
            .map(|v| v.parse().expect("overlap"));
        let t = make_tileable(
            &image,
            TileableOptions {
                overlap_x: overlap,
                overlap_y: overlap,
                memory_budget_mib: None,
            },
        )
        .expect("tileable");
        if let Ok(dir) = std::env::var("WRITE") {
            let (w, h, c) = (t.image.width(), t.image.height(), t.image.channels());
            let tiled = Image::from_fn(3 * w, 3 * h, c, |x, y, k| t.image.pixel(x % w, y % h)[k])
                .expect("3x3");
            std::fs::write(
                format!("{dir}/tileable-{name}-{size}-3x3.png"),
                encode_png(&tiled).expect("png"),
            )
            .expect("write");
            let naive = Image::from_fn(3 * size, 3 * size, c, |x, y, k| {
                image.pixel(x % size, y % size)[k]
            })
            .expect("3x3");
            std::fs::write(
                format!("{dir}/untiled-{name}-{size}-3x3.png"),
                encode_png(&naive).expect("png"),
            )
            .expect("write");
        }
        println!(
            "make tileable {size}x{size}: {:.1} ms (seams {:.2} + {:.2})",
            start.elapsed().as_secs_f64() * 1e3,
            t.seam_cost_x,
            t.seam_cost_y
        );
    }
    let base = resize_bilinear(&load("gravel_128"), 256, 256, Edge::Clamp).expect("base");
    let reference = resize_bilinear(&load("paving_128"), 256, 256, Edge::Clamp).expect("ref");
    let mask: Vec<bool> = (0..256 * 256)
        .map(|i| {
            let (x, y) = ((i % 256) as f32 - 128.0, (i / 256) as f32 - 120.0);
            x * x / 900.0 + y * y / 400.0 <= 1.0
        })
        .collect();
    let mut design = LocalDeformation::new(&base, BrushOptions::default()).expect("brush");
    let start = Instant::now();
    let r = design
        .stroke(&Stroke {
            reference: &reference,
            mask: &mask,
            dx: -20,
            dy: 30,
        })
        .expect("stroke");
    if let Ok(dir) = std::env::var("WRITE") {
        std::fs::write(
            format!("{dir}/brush-base.png"),
            encode_png(&base).expect("png"),
        )
        .expect("write");
        std::fs::write(
            format!("{dir}/brush-result.png"),
            encode_png(design.image()).expect("png"),
        )
        .expect("write");
    }
    println!(
        "brush stroke on 256x256 (60x40 ellipse, window {}x{}): {:.1} ms, {} pixels taken, {} CG iterations",
        r.width,
        r.height,
        start.elapsed().as_secs_f64() * 1e3,
        r.taken,
        r.poisson_iterations
    );
}
