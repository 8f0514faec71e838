//! Image decoding plus exemplar preparation: any bytes either fail to decode with an error or
//! give an image that survives what the page does with an upload (shrink to a working size, crop
//! a region, render RGBA, encode PNG and decode it back unchanged).
#![no_main]

use libfuzzer_sys::fuzz_target;
use texsynth::core::sample::shrink_area;
use texsynth::core::{decode, encode_png, to_rgba8};

fuzz_target!(|data: &[u8]| {
    // The last two bytes choose the working size and the crop; the rest is the file.
    let (file, knobs) = data.split_at(data.len().saturating_sub(2));
    let Ok(image) = decode(file) else { return };
    let (w, h) = (image.width(), image.height());
    assert!(w > 0 && h > 0);
    let side = usize::from(knobs.first().copied().unwrap_or(16)).max(1);
    let longer = w.max(h);
    if longer > side {
        let scaled = |len: usize| (len * side).div_ceil(longer).clamp(1, len);
        let small = shrink_area(&image, scaled(w), scaled(h)).expect("shrinking to a smaller size");
        assert_eq!((small.width(), small.height()), (scaled(w), scaled(h)));
    }
    let c = usize::from(knobs.get(1).copied().unwrap_or(0));
    let _ = image.crop(c % w, c / 16 % h, 1 + c % 7, 1 + c % 5);
    assert_eq!(to_rgba8(&image).len(), w * h * 4);
    if w * h <= 1 << 16 {
        let png = encode_png(&image).expect("encoding a decoded image");
        let back = decode(&png).expect("decoding our own PNG");
        assert_eq!(to_rgba8(&back), to_rgba8(&image), "PNG round trip");
    }
});
