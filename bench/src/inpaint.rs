//! `compare --task inpaint`: hole filling against the peer. Each texture (the largest of its
//! sizes in the folder) gets a centred square hole of 25% and of 40% of its pixels, erased to
//! mid-grey; texsynth's `Inpainting` and the peer's inpaint (texture-synthesis's
//! `inpaint_example`, sampling from the known pixels only, on one thread and on `--threads` or
//! all threads) fill it. Per texture and hole: the time, the coherence of the filled square
//! against the known part (7x7 patches to the nearest patch wholly inside one of the four known
//! rectangles around the hole), its flat fraction, and a seam score: the mean colour step across
//! the hole's boundary over the image's mean step between neighbours (1: the boundary is as busy
//! as the texture; above 1 a seam shows, below 1 the boundary is smoothed over). Lower is better
//! for the first three, nearer 1 for the seam score. Writes `inpaint.json`,
//! `inpaint.md` and a contact sheet per texture and hole (image, mask, ours, the peer's).

use std::path::Path;
use std::time::Instant;

use serde::Serialize;
use texsynth::core::{Image, from_rgba8, to_rgba8};
use texsynth::methods::inpainting::{Options, Session};
use texsynth::methods::quality::coherence_against;
use texsynth::methods::quality::detail::{flat_fraction, flat_threshold};
use texture_synthesis as ts;
use ts::image as image023;

use crate::args::Args;
use crate::contact_sheet::{self, Tile};
use crate::methods::ms;
use crate::prepare::Exemplar;

/// The hole sizes, as shares of the image's pixels.
pub const SHARES: [f64; 2] = [0.25, 0.40];

/// "No worse" allows this much above the peer's figure (the metrics' noise between seeds).
pub const TOLERANCE: f64 = 1.05;

/// One filled hole's figures.
#[derive(Debug, Clone, Serialize)]
pub struct Scores {
    pub ms: f64,
    pub coherence: f64,
    pub flat: f64,
    pub seam: f64,
}

/// One texture and hole.
#[derive(Debug, Clone, Serialize)]
pub struct Row {
    pub texture: String,
    pub share: f64,
    pub size: (usize, usize),
    pub ours: Scores,
    pub peer_one_thread: Scores,
    pub peer_threads: Scores,
    pub contact_sheet: String,
}

#[derive(Serialize)]
struct Report<'a> {
    command: Vec<String>,
    threads: usize,
    tolerance: f64,
    rows: &'a [Row],
}

/// The centred square hole of `share` of a `w` x `h` image: its corner and side.
fn hole(w: usize, h: usize, share: f64) -> (usize, usize, usize) {
    let side = (((w * h) as f64 * share).sqrt() as usize).min(w.min(h) - 2);
    ((w - side) / 2, (h - side) / 2, side)
}

/// Runs the task over `exemplars`, prints the table and writes the files into `args.out`.
pub fn run(args: &Args, exemplars: &[Exemplar], argv: &[String]) -> Result<(), String> {
    let sheets = args.out.join("contact-sheets");
    std::fs::create_dir_all(&sheets)
        .map_err(|e| format!("cannot create {}: {e}", sheets.display()))?;
    let threads = if args.threads > 1 {
        args.threads
    } else {
        std::thread::available_parallelism().map_or(2, |n| n.get())
    };
    let mut rows = Vec::new();
    for (i, ex) in largest_of_each(exemplars).into_iter().enumerate() {
        eprintln!(
            "[{}] {} ({}x{})",
            i + 1,
            ex.name,
            ex.image.width(),
            ex.image.height()
        );
        let image = ex.image.with_channels(3).map_err(|e| e.to_string())?;
        for share in SHARES {
            rows.push(one(
                &image,
                &texture_name(&ex.name),
                share,
                threads,
                args,
                &sheets,
            )?);
        }
    }
    let table = render(&rows, threads);
    print!("{table}");
    let report = Report {
        command: std::env::var("COMPARE_COMMAND")
            .map(|c| vec![c])
            .unwrap_or_else(|_| argv.to_vec()),
        threads,
        tolerance: TOLERANCE,
        rows: &rows,
    };
    let json = args.out.join("inpaint.json");
    let text = serde_json::to_string_pretty(&report).map_err(|e| e.to_string())?;
    std::fs::write(&json, text).map_err(|e| format!("cannot write {}: {e}", json.display()))?;
    let md = args.out.join("inpaint.md");
    std::fs::write(&md, &table).map_err(|e| format!("cannot write {}: {e}", md.display()))?;
    println!(
        "\nwrote {}, {} and the contact sheets in {}",
        json.display(),
        md.display(),
        sheets.display()
    );
    Ok(())
}

/// The texture's name without its size suffix (`brick_full` -> `brick`).
fn texture_name(name: &str) -> String {
    name.rsplit_once('_')
        .map_or(name, |(stem, _)| stem)
        .to_string()
}

/// One exemplar per texture: the largest of the files that share a name before their size.
fn largest_of_each(exemplars: &[Exemplar]) -> Vec<&Exemplar> {
    let mut best: Vec<&Exemplar> = Vec::new();
    for ex in exemplars {
        let area = |e: &Exemplar| u64::from(e.original_size.0) * u64::from(e.original_size.1);
        match best
            .iter_mut()
            .find(|b| texture_name(&b.name) == texture_name(&ex.name))
        {
            Some(b) if area(ex) > area(b) => *b = ex,
            Some(_) => {}
            None => best.push(ex),
        }
    }
    best
}

fn one(
    image: &Image,
    name: &str,
    share: f64,
    threads: usize,
    args: &Args,
    sheets: &Path,
) -> Result<Row, String> {
    let (w, h) = (image.width(), image.height());
    let (x0, y0, side) = hole(w, h, share);
    let inside = |x: usize, y: usize| x >= x0 && x < x0 + side && y >= y0 && y < y0 + side;
    let mask: Vec<u8> = (0..w * h).map(|i| u8::from(inside(i % w, i / w))).collect();
    let erased = Image::from_fn(w, h, 3, |x, y, k| {
        if inside(x, y) {
            0.5
        } else {
            image.pixel(x, y)[k]
        }
    })
    .map_err(|e| e.to_string())?;
    let seed = args.seeds[0];

    let start = Instant::now();
    let mut session = Session::new(
        &erased,
        &mask,
        None,
        Options {
            seed,
            ..Options::default()
        },
    )
    .map_err(|e| format!("{name}: {e}"))?;
    while !session.is_done() {
        session.step().map_err(|e| format!("{name}: {e}"))?;
    }
    let ours_ms = ms(start);
    let ours = session.output().map_err(|e| e.to_string())?;

    let (peer1, peer1_ms) = peer(&erased, &mask, seed, 1)?;
    let (peer_n, peer_n_ms) = peer(&erased, &mask, seed, threads)?;
    let score = |out: &Image, ms: f64| scores(image, out, (x0, y0, side), ms);
    let row_scores = (
        score(&ours, ours_ms)?,
        score(&peer1, peer1_ms)?,
        score(&peer_n, peer_n_ms)?,
    );

    let mask_image = Image::from_fn(w, h, 3, |x, y, _| if inside(x, y) { 1.0 } else { 0.0 })
        .map_err(|e| e.to_string())?;
    let note = |s: &Scores| {
        format!(
            "{:.0} ms coh {:.4} flat {:.2} seam {:.2}",
            s.ms, s.coherence, s.flat, s.seam
        )
    };
    let tiles = [
        Tile {
            label: "image".into(),
            note: format!("{w}x{h}"),
            image: Some(image),
        },
        Tile {
            label: "mask".into(),
            note: format!("{:.0}% hole", share * 100.0),
            image: Some(&mask_image),
        },
        Tile {
            label: "texsynth".into(),
            note: note(&row_scores.0),
            image: Some(&ours),
        },
        Tile {
            label: "peer".into(),
            note: note(&row_scores.1),
            image: Some(&peer1),
        },
    ];
    let file = format!("{name}-{:.0}.png", share * 100.0);
    let sheet = sheets.join(&file);
    let title = format!("{name}  {:.0}% hole  seed {seed}", share * 100.0);
    contact_sheet::write(&sheet, &title, &tiles, (w, h))?;
    Ok(Row {
        texture: name.to_string(),
        share,
        size: (w, h),
        ours: row_scores.0,
        peer_one_thread: row_scores.1,
        peer_threads: row_scores.2,
        contact_sheet: sheet.display().to_string(),
    })
}

/// The peer's inpaint of `erased` over `mask` (1: fill), sampling from the known pixels only.
fn peer(erased: &Image, mask: &[u8], seed: u64, threads: usize) -> Result<(Image, f64), String> {
    let (w, h) = (erased.width() as u32, erased.height() as u32);
    let input = image023::RgbaImage::from_raw(w, h, to_rgba8(erased)).ok_or("bad buffer")?;
    // The peer keeps pixels whose mask is white and fills the rest.
    let keep: Vec<u8> = mask
        .iter()
        .flat_map(|&m| {
            let v = if m == 0 { 255 } else { 0 };
            [v, v, v, 255]
        })
        .collect();
    let keep = image023::RgbaImage::from_raw(w, h, keep).ok_or("bad mask buffer")?;
    let keep = image023::DynamicImage::ImageRgba8(keep);
    let start = Instant::now();
    let example = ts::Example::builder(image023::DynamicImage::ImageRgba8(input))
        .set_sample_method(keep.clone());
    let session = ts::Session::builder()
        .inpaint_example(keep, example, ts::Dims::new(w, h))
        .seed(seed)
        .max_thread_count(threads)
        .build()
        .map_err(|e| format!("texture-synthesis: {e}"))?;
    let out = session.run(None).into_image().to_rgba8();
    let elapsed = ms(start);
    let image = from_rgba8(out.width() as usize, out.height() as usize, out.as_raw())
        .map_err(|e| e.to_string())?;
    Ok((image.with_channels(3).map_err(|e| e.to_string())?, elapsed))
}

/// The figures of `out` filled over the hole at (x0, y0) of `side`, against `original`.
fn scores(
    original: &Image,
    out: &Image,
    (x0, y0, side): (usize, usize, usize),
    ms: f64,
) -> Result<Scores, String> {
    let (w, h) = (original.width(), original.height());
    let crop = |img: &Image, x: usize, y: usize, cw: usize, ch: usize| {
        img.crop(x, y, cw, ch).map_err(|e| e.to_string())
    };
    let filled = crop(out, x0, y0, side, side)?;
    // The known part as the four rectangles around the hole.
    let parts = [
        crop(original, 0, 0, w, y0)?,
        crop(original, 0, y0 + side, w, h - y0 - side)?,
        crop(original, 0, y0, x0, side)?,
        crop(original, x0 + side, y0, w - x0 - side, side)?,
    ];
    let coherence = coherence_against(&parts, &filled).map_err(|e| e.to_string())?;
    let flat = flat_fraction(&filled, flat_threshold(original));
    let step = |img: &Image, a: (usize, usize), b: (usize, usize)| -> f64 {
        img.pixel(a.0, a.1)
            .iter()
            .zip(img.pixel(b.0, b.1))
            .map(|(p, q)| f64::from((p - q).abs()))
            .sum::<f64>()
    };
    let inside = |x: usize, y: usize| x >= x0 && x < x0 + side && y >= y0 && y < y0 + side;
    let (mut across, mut n_across, mut all, mut n_all) = (0.0, 0usize, 0.0, 0usize);
    for y in 0..h {
        for x in 0..w {
            for (nx, ny) in [(x + 1, y), (x, y + 1)] {
                if nx >= w || ny >= h {
                    continue;
                }
                all += step(original, (x, y), (nx, ny));
                n_all += 1;
                if inside(x, y) != inside(nx, ny) {
                    across += step(out, (x, y), (nx, ny));
                    n_across += 1;
                }
            }
        }
    }
    let seam = (across / n_across.max(1) as f64) / (all / n_all.max(1) as f64).max(1e-9);
    Ok(Scores {
        ms,
        coherence,
        flat,
        seam,
    })
}

/// Whether `ours` is no worse than `peer` within [`TOLERANCE`]: coherence no higher, and the seam
/// score no farther from 1 (in ratio: a boundary twice as busy and one half as busy as the
/// texture are equally far).
pub fn no_worse(ours: &Scores, peer: &Scores) -> bool {
    ours.coherence <= peer.coherence * TOLERANCE
        && ours.seam.ln().abs() <= peer.seam.ln().abs() + TOLERANCE.ln()
}

/// The table: per texture and hole, the figures side by side, then the count of holes where
/// texsynth is faster than the peer and no worse (see [`no_worse`]).
fn render(rows: &[Row], threads: usize) -> String {
    let mut out = format!(
        "| texture | hole | texsynth ms | peer ms (1 thread) | peer ms ({threads} threads) | coherence texsynth / peer | flat texsynth / peer | seam texsynth / peer |\n|---|---|---|---|---|---|---|---|\n"
    );
    for r in rows {
        out += &format!(
            "| {} | {:.0}% | {:.0} | {:.0} | {:.0} | {:.4} / {:.4} | {:.2} / {:.2} | {:.2} / {:.2} |\n",
            r.texture,
            r.share * 100.0,
            r.ours.ms,
            r.peer_one_thread.ms,
            r.peer_threads.ms,
            r.ours.coherence,
            r.peer_one_thread.coherence,
            r.ours.flat,
            r.peer_one_thread.flat,
            r.ours.seam,
            r.peer_one_thread.seam,
        );
    }
    for share in SHARES {
        let of: Vec<&Row> = rows.iter().filter(|r| r.share == share).collect();
        let good = |peer: fn(&Row) -> &Scores| {
            of.iter()
                .filter(|r| {
                    let p = peer(r);
                    r.ours.ms < p.ms && no_worse(&r.ours, p)
                })
                .count()
        };
        out += &format!(
            "\n{:.0}% hole: texsynth faster and no worse on coherence and seam score (within {:.0}%; the seam score no farther from 1) on {} of {} textures against the peer on 1 thread, {} of {} against it on {threads} threads.\n",
            share * 100.0,
            (TOLERANCE - 1.0) * 100.0,
            good(|r| &r.peer_one_thread),
            of.len(),
            good(|r| &r.peer_threads),
            of.len(),
        );
    }
    out
}
