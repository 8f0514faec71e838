//! Scores the frames `flow_frames` wrote, with today's metrics: `cargo run --profile explore
//! --example score_frames -- EXEMPLAR.png DIR...`. For each folder, frame 1 and the means over
//! frames 30-60 of the flat fraction, coherence, gradient energy (mean squared central
//! difference per value: how much detail there is to move) and flow energy, and the flow energy
//! per unit of gradient energy, which compares how closely frames of unequal detail follow the
//! flow.

use texsynth::core::gradient::gradients;
use texsynth::core::{Edge, Image, decode};
use texsynth::methods::quality::quality;

fn gradient_energy(image: &Image) -> f64 {
    let (dx, dy) = gradients(image, Edge::Clamp);
    let sum: f64 = dx
        .data()
        .iter()
        .chain(dy.data())
        .map(|&v| f64::from(v * v))
        .sum();
    sum / image.data().len() as f64
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let exemplar = decode(&std::fs::read(&args[0]).expect("exemplar")).expect("decodes");
    println!("exemplar gradient energy {:.5}", gradient_energy(&exemplar));
    for dir in &args[1..] {
        let tsv = std::fs::read_to_string(format!("{dir}/flow.tsv")).expect("flow.tsv");
        // (frame, flat, coherence, gradient energy, flow energy)
        let rows: Vec<(usize, f64, f64, f64, f64)> = tsv
            .lines()
            .skip(1)
            .map(|line| {
                let (frame, flow) = line.split_once('\t').expect("two columns");
                let image =
                    decode(&std::fs::read(format!("{dir}/frame{frame}.png")).expect("frame"))
                        .expect("decodes");
                let q = quality(&exemplar, &image).expect("quality");
                let frame = frame.parse().expect("frame number");
                (
                    frame,
                    q.flat,
                    q.coherence,
                    gradient_energy(&image),
                    flow.parse().expect("energy"),
                )
            })
            .collect();
        let later: Vec<_> = rows.iter().filter(|r| r.0 >= 30).collect();
        let mean = |f: fn(&(usize, f64, f64, f64, f64)) -> f64| {
            later.iter().map(|r| f(r)).sum::<f64>() / later.len() as f64
        };
        let first = rows[0];
        let (flat, coherence, gradient, flow) =
            (mean(|r| r.1), mean(|r| r.2), mean(|r| r.3), mean(|r| r.4));
        println!(
            "{dir}: frame 1 flat {:.3} coherence {:.6} gradient {:.5}; frames 30-60 flat {flat:.3} ({:.2}x), coherence {coherence:.6} ({:.2}x), gradient {gradient:.5} ({:.2}x), flow energy {flow:.6}, per unit gradient {:.3}",
            first.1,
            first.2,
            first.3,
            flat / first.1,
            coherence / first.2,
            gradient / first.3,
            flow / gradient
        );
    }
}
