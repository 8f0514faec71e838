//! Command-line options. Hand-parsed (a dozen flags do not need a parser crate); every bad value
//! is refused with a message naming the flag, before any work starts.

use std::path::PathBuf;

use crate::methods::Method;

pub const USAGE: &str = "\
usage: compare [options]
  --dir DIR             folder of exemplar images, PNG or JPEG (default: www/samples)
  --size WxH            output size (default: 256x256)
  --seeds 1,2,3         seeds; wall time is the median over them, quality the mean (default: 1,2,3)
  --methods a,b,...     any of optimization, graphcut-random, graphcut-entire, graphcut-sub, features, peer
                        (default: all)
  --crop WxH            cut the centre WxH out of each exemplar first (default: no crop)
  --exemplar-size N     then shrink so the longer side is at most N; 0 keeps any size (default: 256)
  --out DIR             where the results go (default: results/compare; results/inpaint for
                        --task inpaint)
  --threads N           threads for texsynth (rayon; the threaded wasm module) and the peer alike;
                        above 1 needs the parallel feature (default: 1)
  --wasm FILE           timings of the wasm build in Node to merge (scripts/compare_wasm.mjs)
  --task T              synthesis (the methods above, default) or inpaint (a centred hole of 25%
                        and of 40% in each texture, the largest of its sizes, filled by texsynth's
                        Inpainting and the peer's inpaint; native only)
  --prepare-only        only write the prepared exemplars and plan.json, print the plan's path
  --help                this text";

#[derive(Debug, Clone, PartialEq)]
pub struct Args {
    pub dir: PathBuf,
    pub width: usize,
    pub height: usize,
    pub seeds: Vec<u64>,
    pub methods: Vec<Method>,
    pub crop: Option<(usize, usize)>,
    pub exemplar_size: usize,
    pub out: PathBuf,
    pub wasm: Option<PathBuf>,
    pub prepare_only: bool,
    pub threads: usize,
    pub task: Task,
}

/// What `compare` measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Task {
    /// Synthesis from each exemplar by every method.
    Synthesis,
    /// Hole filling (see `inpaint.rs`).
    Inpaint,
}

impl Default for Args {
    fn default() -> Self {
        Args {
            dir: PathBuf::from("www/samples"),
            width: 256,
            height: 256,
            seeds: vec![1, 2, 3],
            methods: Method::ALL.to_vec(),
            crop: None,
            exemplar_size: 256,
            out: PathBuf::from("results/compare"),
            wasm: None,
            prepare_only: false,
            threads: 1,
            task: Task::Synthesis,
        }
    }
}

/// What the command line asks for: a run, or the usage text.
#[derive(Debug, PartialEq)]
pub enum Parsed {
    Run(Args),
    Help,
}

/// The largest output side accepted: far beyond what a benchmark needs, and it keeps a typo like
/// 25600 from allocating gigabytes.
const MAX_OUTPUT_SIDE: usize = 4096;

pub fn parse(argv: &[String]) -> Result<Parsed, String> {
    let mut args = Args::default();
    let mut it = argv.iter();
    while let Some(flag) = it.next() {
        let mut value = || {
            it.next()
                .ok_or_else(|| format!("{flag} needs a value (see --help)"))
        };
        match flag.as_str() {
            "--help" | "-h" => return Ok(Parsed::Help),
            "--prepare-only" => args.prepare_only = true,
            "--dir" => args.dir = PathBuf::from(value()?),
            "--out" => args.out = PathBuf::from(value()?),
            "--wasm" => args.wasm = Some(PathBuf::from(value()?)),
            "--size" => {
                let (w, h) = size(flag, value()?)?;
                if w > MAX_OUTPUT_SIDE || h > MAX_OUTPUT_SIDE {
                    return Err(format!(
                        "--size: each side must be at most {MAX_OUTPUT_SIDE}, got {w}x{h}"
                    ));
                }
                (args.width, args.height) = (w, h);
            }
            "--crop" => args.crop = Some(size(flag, value()?)?),
            "--exemplar-size" => {
                let v = value()?;
                args.exemplar_size = v.parse().map_err(|_| {
                    format!("--exemplar-size: expected a whole number of pixels, got '{v}'")
                })?;
            }
            "--seeds" => args.seeds = seeds(value()?)?,
            "--threads" => args.threads = threads(value()?)?,
            "--methods" => args.methods = methods(value()?)?,
            "--task" => {
                args.task = match value()?.as_str() {
                    "synthesis" => Task::Synthesis,
                    "inpaint" => Task::Inpaint,
                    other => {
                        return Err(format!(
                            "--task: expected synthesis or inpaint, got '{other}'"
                        ));
                    }
                }
            }
            other => return Err(format!("unknown option '{other}' (see --help)")),
        }
    }
    if args.task == Task::Inpaint && !argv.iter().any(|a| a == "--out") {
        args.out = PathBuf::from("results/inpaint");
    }
    Ok(Parsed::Run(args))
}

/// `WxH` with both sides at least 1.
fn size(flag: &str, v: &str) -> Result<(usize, usize), String> {
    let bad = || format!("{flag}: expected WxH such as 256x256, got '{v}'");
    let (w, h) = v.split_once(['x', 'X']).ok_or_else(bad)?;
    let (w, h): (usize, usize) = (w.parse().map_err(|_| bad())?, h.parse().map_err(|_| bad())?);
    if w == 0 || h == 0 {
        return Err(format!("{flag}: sides must be at least 1, got '{v}'"));
    }
    Ok((w, h))
}

/// The largest thread count accepted: the wasm pool's own limit.
const MAX_THREADS: usize = 64;

/// A thread count from 1 to 64. Above 1, texsynth's methods need the `parallel` feature: a build
/// without it would time the serial code and call it threaded.
fn threads(v: &str) -> Result<usize, String> {
    let n: usize = v
        .parse()
        .map_err(|_| format!("--threads: expected a whole number, got '{v}'"))?;
    if !(1..=MAX_THREADS).contains(&n) {
        return Err(format!("--threads: expected 1 to {MAX_THREADS}, got {n}"));
    }
    if n > 1 && !cfg!(feature = "parallel") {
        return Err(format!(
            "--threads {n}: this compare binary was built without the parallel feature \
             (scripts/compare.sh builds it so)"
        ));
    }
    Ok(n)
}

/// Comma-separated seeds, no duplicates (a repeated seed would repeat a run and bias the median).
fn seeds(v: &str) -> Result<Vec<u64>, String> {
    let mut out = Vec::new();
    for s in v.split(',') {
        let seed: u64 = s
            .trim()
            .parse()
            .map_err(|_| format!("--seeds: expected numbers like 1,2,3, got '{s}'"))?;
        // The wasm binding takes seeds up to 2^53 - 1 (what a JS number holds exactly).
        if seed >= 1 << 53 {
            return Err(format!("--seeds: each seed must be below 2^53, got {seed}"));
        }
        if out.contains(&seed) {
            return Err(format!("--seeds: seed {seed} is given twice"));
        }
        out.push(seed);
    }
    Ok(out)
}

/// Comma-separated method names, kept in the canonical order so tables always line up the same.
fn methods(v: &str) -> Result<Vec<Method>, String> {
    let mut chosen = Vec::new();
    for name in v.split(',') {
        let m = Method::from_name(name.trim()).ok_or_else(|| {
            let known: Vec<&str> = Method::ALL.iter().map(|m| m.name()).collect();
            format!(
                "--methods: unknown method '{name}', expected some of {}",
                known.join(", ")
            )
        })?;
        chosen.push(m);
    }
    Ok(Method::ALL
        .iter()
        .copied()
        .filter(|m| chosen.contains(m))
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(line: &str) -> Result<Args, String> {
        let argv: Vec<String> = line.split_whitespace().map(String::from).collect();
        parse(&argv).map(|p| match p {
            Parsed::Run(a) => a,
            Parsed::Help => panic!("help"),
        })
    }

    #[test]
    fn defaults_and_every_option() {
        assert_eq!(run("").unwrap(), Args::default());
        let a = run(
            "--dir photos --size 128x64 --seeds 7,3 --methods peer,optimization \
                     --crop 300x200 --exemplar-size 0 --out o --wasm w.json --prepare-only",
        )
        .unwrap();
        assert_eq!(a.dir, PathBuf::from("photos"));
        assert_eq!((a.width, a.height), (128, 64));
        assert_eq!(a.seeds, vec![7, 3]);
        // Canonical order, whatever order they were given in.
        assert_eq!(a.methods, vec![Method::Optimization, Method::Peer]);
        assert_eq!(a.crop, Some((300, 200)));
        assert_eq!(a.exemplar_size, 0);
        assert!(a.prepare_only);
        assert_eq!(a.threads, 1);
        assert_eq!(run("--threads 1").unwrap().threads, 1);
        assert_eq!(run("--threads 2").is_ok(), cfg!(feature = "parallel"));
        assert_eq!(parse(&["--help".into()]), Ok(Parsed::Help));
    }

    #[test]
    fn bad_values_are_named() {
        for (line, needle) in [
            ("--size 256", "--size: expected WxH"),
            ("--size 0x256", "at least 1"),
            ("--size 99999x2", "at most 4096"),
            ("--seeds 1,a", "--seeds"),
            ("--seeds 1,1", "given twice"),
            ("--methods optimization,fast", "unknown method 'fast'"),
            ("--exemplar-size -3", "--exemplar-size"),
            ("--crop", "needs a value"),
            ("--threads 0", "1 to 64"),
            ("--threads two", "--threads"),
            ("--frobnicate", "unknown option"),
        ] {
            let err = run(line).unwrap_err();
            assert!(err.contains(needle), "{line}: {err}");
        }
    }
}
