//! The wavelet-based texture energy (Shen et al. 2009, section 3.3) against the pixel energy on
//! the structured samples: `cargo run --profile explore --example wavelet_sweep -- [SIZE]
//! [SEEDS]` (defaults `256 1,2,3`). For every exemplar and method (pixels, haar, daubechies) it
//! prints the mean over seeds of the time, the quality metrics (coherence, completeness, flat
//! fraction, from `texsynth::methods::quality`) and the final energy (the pixel term, comparable
//! across methods) and the M-step's own energy.
//!
//! Environment: `ONLY=brick,tiles` picks exemplars by prefix; `WEIGHTS=1,4,16` runs the wavelet
//! methods once per detail weight (default: the option's default); `TSV=file` writes the rows as
//! tab-separated values; `WRITE=dir` writes, per exemplar, a contact sheet `<name>.png` (the
//! exemplar, then one output per method, first seed) and every output as
//! `<name>_<method>_s<seed>.png`. Other options from the environment: `MU`, `SEARCH`.

use std::fmt::Write as _;
use std::time::Instant;

use texsynth::core::{Image, decode, encode_png};
use texsynth::methods::optimization::{Energy, EventKind, Options, Session};
use texsynth::methods::quality::quality;
use texsynth::solvers::nn::Search;

const SAMPLES: &[&str] = &[
    "squares_128",
    "planks_128",
    "carpet_128",
    "brick_128",
    "tiles_128",
];

struct Row {
    exemplar: String,
    method: String,
    ms: f64,
    coherence: f64,
    completeness: f64,
    flat: f64,
    energy: f64,
    match_energy: f64,
}

/// Pastes `img` (3 channels) into `canvas` at (x0, y0).
fn paste(canvas: &mut Image, img: &Image, x0: usize, y0: usize) {
    for y in 0..img.height() {
        for x in 0..img.width() {
            let p = img.pixel(x, y).to_vec();
            canvas.pixel_mut(x0 + x, y0 + y).copy_from_slice(&p);
        }
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let size: usize = args.first().map_or(256, |s| s.parse().expect("size"));
    let seeds: Vec<u64> = args
        .get(1)
        .map_or("1,2,3", String::as_str)
        .split(',')
        .map(|s| s.parse().expect("seed"))
        .collect();
    let only = std::env::var("ONLY").unwrap_or_default();
    let write = std::env::var("WRITE").ok();
    if let Some(dir) = &write {
        std::fs::create_dir_all(dir).expect("WRITE dir");
    }
    let defaults = Options::default();
    let weights: Vec<f32> = std::env::var("WEIGHTS").map_or_else(
        |_| vec![defaults.wavelet_detail_weight],
        |v| v.split(',').map(|w| w.parse().expect("weight")).collect(),
    );
    let mu: f32 = std::env::var("MU").map_or(0.0, |v| v.parse().expect("MU"));
    let search = std::env::var("SEARCH").map_or(defaults.search, |v| {
        Search::from_name(&v).expect("SEARCH: patchmatch | kmeans-tree | exact")
    });
    let mut methods: Vec<(String, Energy, f32)> = vec![("pixels".into(), Energy::Pixels, 0.0)];
    for energy in [Energy::Haar, Energy::Daubechies] {
        for &w in &weights {
            let name = if weights.len() == 1 {
                energy.name().to_string()
            } else {
                format!("{}-w{w}", energy.name())
            };
            methods.push((name, energy, w));
        }
    }
    println!(
        "{:<12} {:<15} {:>7} {:>10} {:>12} {:>7} {:>9} {:>9}",
        "exemplar", "method", "ms", "coherence", "completeness", "flat", "energy", "match"
    );
    let mut rows = Vec::new();
    for name in SAMPLES
        .iter()
        .filter(|n| only.is_empty() || only.split(',').any(|f| n.starts_with(f)))
    {
        let path = format!("www/samples/{name}.png");
        let exemplar = decode(&std::fs::read(&path).expect("sample")).expect("decodes");
        let mut sheet = vec![exemplar.with_channels(3).unwrap()];
        for (method, energy, w) in &methods {
            let mut row = Row {
                exemplar: name.to_string(),
                method: method.clone(),
                ms: 0.0,
                coherence: 0.0,
                completeness: 0.0,
                flat: 0.0,
                energy: 0.0,
                match_energy: 0.0,
            };
            for &seed in &seeds {
                let options = Options {
                    output_width: size,
                    output_height: size,
                    seed,
                    energy: *energy,
                    wavelet_detail_weight: *w,
                    mu,
                    search,
                    ..Options::default()
                };
                let start = Instant::now();
                let mut session = Session::new(&exemplar, options).expect("options");
                let last = loop {
                    let event = session.step().expect("step");
                    if event.kind == EventKind::Done {
                        break event;
                    }
                };
                row.ms += start.elapsed().as_secs_f64() * 1e3;
                let out = session.output_full_size().unwrap();
                let q = quality(&exemplar, &out).unwrap();
                row.coherence += q.coherence;
                row.completeness += q.completeness;
                row.flat += q.flat;
                row.energy += last.energy;
                row.match_energy += last.match_energy;
                let rgb = out.with_channels(3).unwrap();
                if let Some(dir) = &write {
                    let file = format!("{dir}/{name}_{method}_s{seed}.png");
                    std::fs::write(file, encode_png(&rgb).unwrap()).unwrap();
                }
                if seed == seeds[0] {
                    sheet.push(rgb);
                }
            }
            let n = seeds.len() as f64;
            for v in [
                &mut row.ms,
                &mut row.coherence,
                &mut row.completeness,
                &mut row.flat,
                &mut row.energy,
                &mut row.match_energy,
            ] {
                *v /= n;
            }
            println!(
                "{:<12} {:<15} {:>7.0} {:>10.5} {:>12.5} {:>7.3} {:>9.5} {:>9.5}",
                row.exemplar,
                row.method,
                row.ms,
                row.coherence,
                row.completeness,
                row.flat,
                row.energy,
                row.match_energy
            );
            rows.push(row);
        }
        if let Some(dir) = &write {
            let gap = 4;
            let width = sheet.iter().map(|i| i.width() + gap).sum::<usize>();
            let mut canvas = Image::from_fn(width, size, 3, |_, _, _| 1.0).unwrap();
            let mut x = 0;
            for img in &sheet {
                paste(&mut canvas, img, x, 0);
                x += img.width() + gap;
            }
            std::fs::write(format!("{dir}/{name}.png"), encode_png(&canvas).unwrap()).unwrap();
        }
    }
    // Per method, the mean over exemplars.
    println!("mean over exemplars:");
    for (method, ..) in &methods {
        let of: Vec<&Row> = rows.iter().filter(|r| &r.method == method).collect();
        let mean = |f: fn(&Row) -> f64| of.iter().map(|r| f(r)).sum::<f64>() / of.len() as f64;
        println!(
            "{:<12} {:<15} {:>7.0} {:>10.5} {:>12.5} {:>7.3} {:>9.5} {:>9.5}",
            "all",
            method,
            mean(|r| r.ms),
            mean(|r| r.coherence),
            mean(|r| r.completeness),
            mean(|r| r.flat),
            mean(|r| r.energy),
            mean(|r| r.match_energy)
        );
    }
    if let Ok(path) = std::env::var("TSV") {
        let mut tsv = String::from(
            "exemplar\tmethod\tms\tcoherence\tcompleteness\tflat\tenergy\tmatch_energy\n",
        );
        for r in &rows {
            writeln!(
                tsv,
                "{}\t{}\t{:.1}\t{:.6}\t{:.6}\t{:.4}\t{:.6}\t{:.6}",
                r.exemplar,
                r.method,
                r.ms,
                r.coherence,
                r.completeness,
                r.flat,
                r.energy,
                r.match_energy
            )
            .unwrap();
        }
        std::fs::write(path, tsv).unwrap();
    }
}
