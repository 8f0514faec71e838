//! Scores outputs against their exemplar with the quality metrics, independently of the method
//! that made them (lower is better for all four): coherence (does every part of the output look
//! like some part of the exemplar?), completeness (does the output use all of the exemplar?),
//! the colour histogram distance, and the flat fraction (how much of the output lost its
//! detail; the exemplar itself scores about 0.10).
//!
//! ```sh
//! cargo run --release --example 07_measure -- www/samples/gravel_64.png
//! ```

#[path = "shared/args.rs"]
mod args;

use texsynth::{Image, Result, Session, graphcut, optimization, quality};

fn run<S: Session>(mut session: S) -> Result<Image> {
    while !session.is_done() {
        session.step()?;
    }
    session.output()
}

fn main() -> std::result::Result<(), Box<dyn std::error::Error>> {
    let (exemplar, _) = args::exemplar_and_folder("07_measure")?;
    let (w, h) = (2 * exemplar.width(), 2 * exemplar.height());
    // A flat image of the exemplar's mean colour: the worst case the flat fraction catches.
    let mean: Vec<f32> = (0..exemplar.channels())
        .map(|c| {
            exemplar
                .data()
                .iter()
                .skip(c)
                .step_by(exemplar.channels())
                .sum::<f32>()
                / exemplar.pixel_count() as f32
        })
        .collect();
    let outputs = [
        (
            "texture optimisation",
            run(optimization::Session::new(
                &exemplar,
                optimization::Options {
                    output_width: w,
                    output_height: h,
                    ..Default::default()
                },
            )?)?,
        ),
        (
            "graph cut",
            run(graphcut::Session::new(
                &exemplar,
                graphcut::Options {
                    output_width: w,
                    output_height: h,
                    ..Default::default()
                },
            )?)?,
        ),
        (
            "flat colour",
            Image::from_fn(w, h, exemplar.channels(), |_, _, c| mean[c])?,
        ),
    ];
    println!(
        "{:<22} {:>10} {:>12} {:>10} {:>6}",
        "output", "coherence", "completeness", "histogram", "flat"
    );
    for (name, output) in &outputs {
        let q = quality(&exemplar, output)?;
        println!(
            "{name:<22} {:>10.4} {:>12.4} {:>10.4} {:>6.3}",
            q.coherence, q.completeness, q.histogram, q.flat
        );
    }
    Ok(())
}
