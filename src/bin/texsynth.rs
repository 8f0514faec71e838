//! The command line: inpainting and uncrop of PNG or JPEG files.
//!
//! ```text
//! texsynth inpaint IN.png --mask MASK.png -o OUT.png [--exemplar EX.png] [--seed N] [--patch-size N]
//! texsynth uncrop IN.png --border 64 -o OUT.png [--seed N]
//! texsynth uncrop IN.png --border TOP,RIGHT,BOTTOM,LEFT -o OUT.png
//! ```
//!
//! A mask pixel marks the hole where it is not black (any channel non-zero, alpha ignored).

use std::process::ExitCode;

use texsynth::inpainting::{Border, Options, Session, extend};
use texsynth::{Image, decode, encode_png};

const USAGE: &str = "usage:
  texsynth inpaint IN --mask MASK -o OUT [--exemplar EX] [--seed N] [--patch-size N] [--optimize yes|no]
  texsynth uncrop IN --border N|TOP,RIGHT,BOTTOM,LEFT -o OUT [--exemplar EX] [--seed N] [--patch-size N] [--optimize yes|no]
A mask pixel that is not black marks the hole. Images are PNG or JPEG; the output is PNG.";

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("texsynth: {message}");
            ExitCode::from(2)
        }
    }
}

/// The parsed flags of a command: its one positional input and its `--name value` pairs.
struct Args {
    input: String,
    flags: Vec<(String, String)>,
}

impl Args {
    fn parse(args: &[String], known: &[&str]) -> Result<Args, String> {
        let (mut input, mut flags) = (None, Vec::new());
        let mut it = args.iter();
        while let Some(a) = it.next() {
            if let Some(name) = a
                .strip_prefix("--")
                .or(a.strip_prefix('-').filter(|n| *n == "o"))
            {
                if !known.contains(&name) {
                    return Err(format!("unknown option {a}\n{USAGE}"));
                }
                let value = it.next().ok_or(format!("{a} needs a value"))?;
                flags.push((name.to_string(), value.clone()));
            } else if input.replace(a.clone()).is_some() {
                return Err(format!("more than one input image given ({a})\n{USAGE}"));
            }
        }
        let input = input.ok_or(format!("no input image given\n{USAGE}"))?;
        Ok(Args { input, flags })
    }

    fn get(&self, name: &str) -> Option<&str> {
        self.flags
            .iter()
            .rev()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.as_str())
    }

    fn number(&self, name: &str) -> Result<Option<usize>, String> {
        self.get(name)
            .map(|v| {
                v.parse()
                    .map_err(|_| format!("--{name} must be a whole number, got {v:?}"))
            })
            .transpose()
    }

    fn options(&self) -> Result<Options, String> {
        let mut options = Options::default();
        if let Some(seed) = self.number("seed")? {
            options.seed = seed as u64;
        }
        if let Some(side) = self.number("patch-size")? {
            options.patch_size = side;
        }
        match self.get("optimize") {
            None | Some("yes") => {}
            Some("no") => options.optimize = false,
            Some(other) => return Err(format!("--optimize takes yes or no, got {other:?}")),
        }
        Ok(options)
    }
}

fn run(args: &[String]) -> Result<(), String> {
    let known = [
        "mask",
        "o",
        "exemplar",
        "seed",
        "patch-size",
        "border",
        "optimize",
    ];
    match args.first().map(String::as_str) {
        Some("inpaint") => {
            let a = Args::parse(&args[1..], &known)?;
            let image = read(&a.input)?;
            let mask_path = a
                .get("mask")
                .ok_or(format!("inpaint needs --mask\n{USAGE}"))?;
            let mask = read(mask_path)?;
            if (mask.width(), mask.height()) != (image.width(), image.height()) {
                return Err(format!(
                    "the mask {mask_path} is {}x{}, the image {}x{}",
                    mask.width(),
                    mask.height(),
                    image.width(),
                    image.height()
                ));
            }
            fill(&a, &image, &hole_of(&mask))
        }
        Some("uncrop") => {
            let a = Args::parse(&args[1..], &known)?;
            let image = read(&a.input)?;
            let border = parse_border(a.get("border").ok_or("uncrop needs --border")?)?;
            let (big, mask) = extend(&image, border).map_err(|e| e.to_string())?;
            fill(&a, &big, &mask)
        }
        Some("-h" | "--help" | "help") => {
            println!("{USAGE}");
            Ok(())
        }
        Some(other) => Err(format!("unknown command {other:?}\n{USAGE}")),
        None => Err(USAGE.to_string()),
    }
}

/// Runs an inpainting of `image` over `mask` to the end and writes it where `-o` says.
fn fill(a: &Args, image: &Image, mask: &[u8]) -> Result<(), String> {
    let out = a
        .get("o")
        .ok_or(format!("no output given (-o OUT.png)\n{USAGE}"))?;
    let exemplar = a.get("exemplar").map(read).transpose()?;
    let exemplar = exemplar
        .map(|e| e.with_channels(image.channels()))
        .transpose()
        .map_err(|e| e.to_string())?;
    let mut session =
        Session::new(image, mask, exemplar.as_ref(), a.options()?).map_err(|e| e.to_string())?;
    while !session.is_done() {
        session.step().map_err(|e| e.to_string())?;
    }
    let png =
        encode_png(&session.output().map_err(|e| e.to_string())?).map_err(|e| e.to_string())?;
    std::fs::write(out, png).map_err(|e| format!("cannot write {out}: {e}"))
}

fn read(path: &str) -> Result<Image, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("cannot read {path}: {e}"))?;
    decode(&bytes).map_err(|e| format!("{path}: {e}"))
}

/// One byte per pixel: 1 where any colour channel is not 0.
fn hole_of(mask: &Image) -> Vec<u8> {
    let c = mask.channels();
    let colours = if c == 2 || c == 4 { c - 1 } else { c };
    mask.data()
        .chunks_exact(c)
        .map(|p| u8::from(p[..colours].iter().any(|&v| v > 0.0)))
        .collect()
}

fn parse_border(text: &str) -> Result<Border, String> {
    let widths: Vec<usize> = text
        .split(',')
        .map(|v| v.trim().parse())
        .collect::<Result<_, _>>()
        .map_err(|_| format!("--border takes N or TOP,RIGHT,BOTTOM,LEFT, got {text:?}"))?;
    match widths[..] {
        [n] => Ok(Border::all(n)),
        [top, right, bottom, left] => Ok(Border {
            top,
            right,
            bottom,
            left,
        }),
        _ => Err(format!(
            "--border takes N or TOP,RIGHT,BOTTOM,LEFT, got {text:?}"
        )),
    }
}
