//! `compare`: speed and quality of texsynth's methods side by side with the texture-synthesis
//! crate, on any folder of textures. scripts/compare.sh is the one command that runs it (with
//! the wasm timings from scripts/compare_wasm.mjs); `compare --help` lists the options.
//!
//! Per exemplar: prepare it (prepare.rs), time every method and seed natively and score the
//! outputs (runner.rs), draw the contact sheet (contact_sheet.rs). Then print the tables and write
//! results.json / results.tsv (report.rs).

mod args;
mod contact_sheet;
mod font;
mod inpaint;
mod methods;
mod peer;
mod prepare;
mod report;
mod runner;
mod stats;
mod table;
mod threads;
mod wasm;

use std::process::ExitCode;

use args::{Args, Parsed};
use contact_sheet::Tile;
use report::{ExemplarInfo, Machine, Report};

fn main() -> ExitCode {
    let argv: Vec<String> = std::env::args().collect();
    match args::parse(&argv[1..]) {
        Err(message) => {
            eprintln!("compare: {message}\n\n{}", args::USAGE);
            ExitCode::from(2)
        }
        Ok(Parsed::Help) => {
            println!("{}", args::USAGE);
            ExitCode::SUCCESS
        }
        Ok(Parsed::Run(args)) => match run(&args, &argv) {
            Ok(()) => ExitCode::SUCCESS,
            Err(message) => {
                eprintln!("compare: {message}");
                ExitCode::FAILURE
            }
        },
    }
}

fn run(args: &Args, argv: &[String]) -> Result<(), String> {
    let files = prepare::list(&args.dir)?;
    if files.is_empty() {
        return Err(format!("no PNG or JPEG files in {}", args.dir.display()));
    }
    let prepared_dir = args.out.join("exemplars");
    let (exemplars, skipped) =
        prepare::prepare_all(&files, args.crop, args.exemplar_size, &prepared_dir)?;
    for s in &skipped {
        eprintln!("compare: skipped {}: {}", s.source.display(), s.reason);
    }
    if exemplars.is_empty() {
        return Err(format!(
            "none of the images in {} could be used",
            args.dir.display()
        ));
    }
    if args.prepare_only {
        // The path is the only line on stdout, for scripts/compare.sh to pass on to Node.
        println!("{}", wasm::write_plan(args, &exemplars)?.display());
        return Ok(());
    }
    if args.task == args::Task::Inpaint {
        return inpaint::run(args, &exemplars, argv);
    }
    let wasm = args
        .wasm
        .as_deref()
        .map(|p| wasm::load(p, args, &exemplars))
        .transpose()?;

    let sheets_dir = args.out.join("contact-sheets");
    std::fs::create_dir_all(&sheets_dir)
        .map_err(|e| format!("cannot create {}: {e}", sheets_dir.display()))?;
    let size = (args.width, args.height);
    let pool = threads::Pool::new(args.threads)?;
    let (mut infos, mut results) = (Vec::new(), Vec::new());
    for (i, ex) in exemplars.iter().enumerate() {
        eprintln!(
            "[{}/{}] {} ({}x{})",
            i + 1,
            exemplars.len(),
            ex.name,
            ex.image.width(),
            ex.image.height()
        );
        let runs = runner::run_exemplar(
            ex,
            &args.methods,
            &args.seeds,
            size,
            &pool,
            args.threads,
            wasm.as_ref(),
        );
        let sheet = sheets_dir.join(format!("{}.png", ex.name));
        let order = write_sheet(&sheet, ex, &runs, args)?;
        infos.push(ExemplarInfo {
            name: ex.name.clone(),
            source: ex.source.clone(),
            original_size: ex.original_size,
            size: (ex.image.width(), ex.image.height()),
            png: ex.png_path.clone(),
            png_hash: ex.png_hash.clone(),
            contact_sheet: sheet,
            contact_sheet_order: order,
        });
        results.extend(report::entries(&ex.name, runs));
    }

    let report = Report {
        command: std::env::var("COMPARE_COMMAND")
            .map(|c| vec![c])
            .unwrap_or_else(|_| argv.to_vec()),
        machine: Machine::detect(),
        node: wasm.as_ref().map(|w| w.node.clone()),
        wasm_bytes: wasm.as_ref().and_then(|w| w.wasm_bytes),
        dir: args.dir.clone(),
        output_size: size,
        seeds: args.seeds.clone(),
        threads: args.threads,
        methods: args.methods.iter().map(|m| m.name()).collect(),
        crop: args.crop,
        exemplar_size: args.exemplar_size,
        notes: report::NOTES.to_vec(),
        exemplars: infos,
        skipped: skipped.into_iter().map(|s| (s.source, s.reason)).collect(),
        summary: report::summaries(&args.methods, &results),
        results,
    };
    print!("{}", report::render(&report));
    let (json, tsv) = report::write_files(&report, &args.out)?;
    println!(
        "\nwrote {}, {} and the contact sheets in {}",
        json.display(),
        tsv.display(),
        sheets_dir.display()
    );
    Ok(())
}

/// Draws the exemplar's contact sheet; returns the captions left to right.
fn write_sheet(
    path: &std::path::Path,
    ex: &prepare::Exemplar,
    runs: &[runner::MethodRuns],
    args: &Args,
) -> Result<Vec<String>, String> {
    let mut tiles = vec![Tile {
        label: "exemplar".into(),
        note: format!("{}x{}", ex.image.width(), ex.image.height()),
        image: Some(&ex.image),
    }];
    for m in runs {
        let quality = m.runs.iter().find(|r| r.seed == args.seeds[0]);
        let note = match (m.first_ms, quality) {
            (Some(ms), Some(q)) => format!(
                "{} ms coh {} cmp {} flat {}",
                table::ms(Some(ms)),
                table::metric(Some(q.coherence)),
                table::metric(Some(q.completeness)),
                table::flat(Some(q.flat))
            ),
            _ => "failed".into(),
        };
        tiles.push(Tile {
            label: m.method.name().into(),
            note,
            image: m.first_output.as_ref(),
        });
    }
    let title = format!(
        "{}  {}x{} output  seed {}",
        ex.name, args.width, args.height, args.seeds[0]
    );
    contact_sheet::write(path, &title, &tiles, (args.width, args.height))?;
    Ok(tiles.into_iter().map(|t| t.label).collect())
}
