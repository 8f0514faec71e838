//! Texture optimization over a folder of exemplars with every quality metric, the flat fraction
//! first: `cargo run --profile explore --example detail_sweep -- [DIR] [SIZE] [SEEDS]`
//! (defaults `www/samples 256 1,2,3`). Options come from the environment, by their JS names
//! (`MU=10 M_STEP_MU=1 COMPLETENESS=0 R=2 HISTOGRAM_MATCHING=0 ITERATIONS=3 START=patches`). Prints one line per exemplar
//! (mean over seeds) and the worst cases; `ONLY=paving,stone_64` picks exemplars by prefix;
//! `TRACE=1` prints every step of the first seed with the flat fraction at the end of each
//! level; `SHEET=file.png` writes every first-seed output side by side (one row per exemplar
//! size), so the figures can be checked against the pictures.

use std::time::Instant;

use texsynth::core::{Image, decode, encode_png};
use texsynth::methods::optimization::{EventKind, Options, Session};
use texsynth::methods::quality::quality;

fn env_f32(name: &str) -> Option<f32> {
    std::env::var(name)
        .ok()
        .map(|v| v.parse().expect("a number"))
}

fn options(size: usize, seed: u64) -> Options {
    let mut o = Options {
        output_width: size,
        output_height: size,
        seed,
        ..Options::default()
    };
    if let Some(v) = env_f32("MU") {
        o.mu = v;
    }
    o.m_step_mu = env_f32("M_STEP_MU");
    if let Some(v) = env_f32("COMPLETENESS") {
        o.completeness = v;
    }
    if let Some(v) = env_f32("R") {
        o.r = v;
    }
    if let Some(v) = env_f32("HISTOGRAM_MATCHING") {
        o.histogram_matching = v;
    }
    if let Some(v) = env_f32("ITERATIONS") {
        o.iterations = v as usize;
    }
    if let Ok(v) = std::env::var("START") {
        o.start =
            texsynth::methods::optimization::Start::from_name(&v).expect("graphcut or patches");
    }
    o
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let dir = args.first().map_or("www/samples", String::as_str);
    let size: usize = args.get(1).map_or(256, |s| s.parse().expect("size"));
    let seeds: Vec<u64> = args
        .get(2)
        .map_or("1,2,3", String::as_str)
        .split(',')
        .map(|s| s.parse().expect("seed"))
        .collect();
    let filter = std::env::var("ONLY").unwrap_or_default();
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("dir")
        .filter_map(|e| {
            let name = e.ok()?.file_name().into_string().ok()?;
            let stem = name.strip_suffix(".png")?;
            (stem.ends_with("_128") || stem.ends_with("_64")).then(|| stem.to_string())
        })
        .filter(|n| filter.is_empty() || filter.split(',').any(|f| n.starts_with(f)))
        .collect();
    names.sort_by_key(|n| (n.ends_with("_64"), n.clone()));
    println!(
        "{:<14} {:>7} {:>9} {:>10} {:>12} {:>9} {:>8}",
        "exemplar", "flat", "worst", "coherence", "completeness", "histogram", "ms"
    );
    let mut rows: Vec<(String, f64)> = Vec::new();
    let mut sheet: Vec<(bool, Image)> = Vec::new();
    for name in &names {
        let exemplar = decode(&std::fs::read(format!("{dir}/{name}.png")).unwrap()).unwrap();
        let (mut f, mut co, mut cp, mut hi, mut ms) = (0.0, 0.0, 0.0, 0.0, 0.0);
        let mut worst_seed = 0.0f64;
        for &seed in &seeds {
            let start = Instant::now();
            let mut session = Session::new(&exemplar, options(size, seed)).unwrap();
            let trace = std::env::var("TRACE").is_ok() && seed == seeds[0];
            loop {
                let event = session.step().unwrap();
                // A level ends when no match changed or its iteration cap is reached.
                let end_of_level = event.kind == EventKind::Done
                    || event.changed == 0
                    || event.iteration == session.options().iterations;
                if trace {
                    let flat = if end_of_level {
                        let out = session.output_full_size().unwrap();
                        quality(&exemplar, &out).unwrap().flat
                    } else {
                        f64::NAN
                    };
                    println!(
                        "  level {} octave {} size {:>2} it {} energy {:.5} changed {:>5} flat {:.3}{}",
                        event.level,
                        event.octave,
                        event.size,
                        event.iteration,
                        event.energy,
                        event.changed,
                        flat,
                        if end_of_level { " *" } else { "" }
                    );
                }
                if event.kind == EventKind::Done {
                    break;
                }
            }
            ms += start.elapsed().as_secs_f64() * 1e3;
            let out = session.output_full_size().unwrap();
            let q = quality(&exemplar, &out).unwrap();
            f += q.flat;
            worst_seed = worst_seed.max(q.flat);
            co += q.coherence;
            cp += q.completeness;
            hi += q.histogram;
            if seed == seeds[0] {
                sheet.push((name.ends_with("_64"), out.with_channels(3).unwrap()));
            }
        }
        let n = seeds.len() as f64;
        println!(
            "{name:<14} {:>7.3} {worst_seed:>9.3} {:>10.5} {:>12.5} {:>9.5} {:>8.0}",
            f / n,
            co / n,
            cp / n,
            hi / n,
            ms / n
        );
        rows.push((name.clone(), f / n));
    }
    let worst = |suffix: &str| {
        rows.iter()
            .filter(|(n, _)| n.ends_with(suffix))
            .map(|r| r.1)
            .fold(0.0f64, f64::max)
    };
    println!(
        "worst flat: 128 {:.3}, 64 {:.3}",
        worst("_128"),
        worst("_64")
    );
    if let Ok(path) = std::env::var("SHEET") {
        let per_row = sheet
            .iter()
            .filter(|s| !s.0)
            .count()
            .max(sheet.iter().filter(|s| s.0).count());
        let rows_n = 1 + usize::from(sheet.iter().any(|s| s.0) && sheet.iter().any(|s| !s.0));
        let (cw, ch) = (per_row * (size + 4), rows_n * (size + 4));
        let mut canvas = Image::from_fn(cw, ch, 3, |_, _, _| 1.0).unwrap();
        let (mut col128, mut col64) = (0, 0);
        for (small, img) in &sheet {
            let (col, row) = if *small && rows_n == 2 {
                col64 += 1;
                (col64 - 1, 1)
            } else {
                col128 += 1;
                (col128 - 1, 0)
            };
            for y in 0..img.height() {
                for x in 0..img.width() {
                    let p = img.pixel(x, y).to_vec();
                    canvas
                        .pixel_mut(col * (size + 4) + x, row * (size + 4) + y)
                        .copy_from_slice(&p);
                }
            }
        }
        std::fs::write(path, encode_png(&canvas).unwrap()).unwrap();
    }
}
