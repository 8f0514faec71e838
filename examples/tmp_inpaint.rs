// Temporary: inpaint IN MASK OUT [key=value...] natively (not committed).
fn main() {
    let a: Vec<String> = std::env::args().skip(1).collect();
    let image = texsynth::decode(&std::fs::read(&a[0]).unwrap()).unwrap();
    let m = texsynth::decode(&std::fs::read(&a[1]).unwrap()).unwrap();
    let mask: Vec<u8> = m
        .data()
        .chunks_exact(m.channels())
        .map(|p| u8::from(p[0] > 0.0))
        .collect();
    let mut o = texsynth::inpainting::Options::default();
    for kv in &a[3..] {
        let (k, v) = kv.split_once('=').unwrap();
        match k {
            "c" => o.completeness = v.parse().unwrap(),
            "h" => o.histogram_matching = v.parse().unwrap(),
            "opt" => o.optimize = v == "1",
            "p" => o.patch_size = v.parse().unwrap(),
            "l" => o.levels = v.parse().unwrap(),
            "s" => o.neighbourhood_sizes = v.split(',').map(|x| x.parse().unwrap()).collect(),
            _ => panic!(),
        }
    }
    let t = std::time::Instant::now();
    let mut s = texsynth::inpainting::Session::new(&image, &mask, None, o).unwrap();
    let mut fill_ms = 0.0;
    while !s.is_done() {
        let e = s.step().unwrap();
        if e.stage == texsynth::inpainting::Stage::Fill {
            fill_ms = t.elapsed().as_secs_f64() * 1e3;
        }
    }
    eprintln!(
        "fill {fill_ms:.0} ms, total {:.0} ms",
        t.elapsed().as_secs_f64() * 1e3
    );
    std::fs::write(&a[2], texsynth::encode_png(&s.output().unwrap()).unwrap()).unwrap();
}
