//! Getting pixels in and out: PNG/JPEG bytes (through the `image` crate), raw RGBA8 (what a canvas
//! `ImageData` holds), and RGBA8 for display.

use std::io::Cursor;

use image::{DynamicImage, ImageFormat, ImageReader, Limits};

use super::error::{Error, MAX_PIXELS, MAX_SIDE, Result, check_size};
use super::image::Image;

/// Decodes PNG or JPEG bytes into the fewest channels that keep the picture ([`Image::compact`]):
/// grey is one channel, colour three, and any transparent pixel keeps alpha. The header's size is checked against
/// the limits before any pixel memory is allocated, so a forged 100000x100000 header is refused.
pub fn decode(bytes: &[u8]) -> Result<Image> {
    if bytes.is_empty() {
        return Err(Error::EmptyInput);
    }
    let reader = ImageReader::new(Cursor::new(bytes))
        .with_guessed_format()
        .map_err(|e| Error::Decode(e.to_string()))?;
    let format = reader.format().ok_or_else(|| {
        Error::Decode("the bytes are not a PNG or JPEG image (unknown signature)".into())
    })?;
    if !matches!(format, ImageFormat::Png | ImageFormat::Jpeg) {
        return Err(Error::Decode(format!(
            "{format:?} images are not supported, only PNG and JPEG"
        )));
    }
    let (width, height) = ImageReader::new(Cursor::new(bytes))
        .with_guessed_format()
        .map_err(|e| Error::Decode(e.to_string()))?
        .into_dimensions()
        .map_err(|e| Error::Decode(e.to_string()))?;
    check_size("image", width as usize, height as usize)?;

    let mut reader = reader;
    let mut limits = Limits::default();
    limits.max_image_width = Some(MAX_SIDE as u32);
    limits.max_image_height = Some(MAX_SIDE as u32);
    // Room for the decoder's own buffer at 16 bits per channel, RGBA.
    limits.max_alloc = Some((MAX_PIXELS * 8) as u64);
    reader.limits(limits);
    let decoded = reader.decode().map_err(|e| Error::Decode(e.to_string()))?;
    from_dynamic(&decoded)
}

/// Converts a decoded `image` crate picture, choosing the smallest channel count that keeps it.
/// The layouts PNG and JPEG decode to are converted here directly: the `image` crate's generic
/// conversion (`to_rgba32f`) brings colour-space machinery into the wasm build that these
/// layouts never need (about 5 KB of the gzipped package).
fn from_dynamic(decoded: &DynamicImage) -> Result<Image> {
    let (width, height) = (decoded.width() as usize, decoded.height() as usize);
    let rgba = match decoded {
        DynamicImage::ImageLuma8(b) => to_rgba(b.as_raw(), 1, |v| f32::from(v) / 255.0),
        DynamicImage::ImageLumaA8(b) => to_rgba(b.as_raw(), 2, |v| f32::from(v) / 255.0),
        DynamicImage::ImageRgb8(b) => to_rgba(b.as_raw(), 3, |v| f32::from(v) / 255.0),
        DynamicImage::ImageRgba8(b) => to_rgba(b.as_raw(), 4, |v| f32::from(v) / 255.0),
        DynamicImage::ImageLuma16(b) => to_rgba(b.as_raw(), 1, |v| f32::from(v) / 65535.0),
        DynamicImage::ImageLumaA16(b) => to_rgba(b.as_raw(), 2, |v| f32::from(v) / 65535.0),
        DynamicImage::ImageRgb16(b) => to_rgba(b.as_raw(), 3, |v| f32::from(v) / 65535.0),
        DynamicImage::ImageRgba16(b) => to_rgba(b.as_raw(), 4, |v| f32::from(v) / 65535.0),
        DynamicImage::ImageRgb32F(b) => to_rgba(b.as_raw(), 3, |v| v),
        DynamicImage::ImageRgba32F(b) => to_rgba(b.as_raw(), 4, |v| v),
        other => {
            return Err(Error::Decode(format!(
                "unsupported pixel layout {:?}",
                other.color()
            )));
        }
    };
    Image::from_vec(width, height, 4, rgba)?.compact()
}

/// Interleaved RGBA values in 0..1 from `channels` values per pixel (grey, grey + alpha, RGB or
/// RGBA); missing alpha is opaque.
fn to_rgba<T: Copy>(raw: &[T], channels: usize, value: impl Fn(T) -> f32) -> Vec<f32> {
    let mut out = Vec::with_capacity(raw.len() / channels * 4);
    for p in raw.chunks_exact(channels) {
        let v: [f32; 4] = match channels {
            1 => [value(p[0]), value(p[0]), value(p[0]), 1.0],
            2 => [value(p[0]), value(p[0]), value(p[0]), value(p[1])],
            3 => [value(p[0]), value(p[1]), value(p[2]), 1.0],
            _ => [value(p[0]), value(p[1]), value(p[2]), value(p[3])],
        };
        out.extend_from_slice(&v);
    }
    out
}

/// Wraps raw RGBA8 pixels (a canvas `ImageData`), compacted like [`decode`].
pub fn from_rgba8(width: usize, height: usize, rgba: &[u8]) -> Result<Image> {
    check_rgba8(width, height, rgba.len())?;
    let data: Vec<f32> = rgba.iter().map(|&v| f32::from(v) / 255.0).collect();
    Image::from_vec(width, height, 4, data)?.compact()
}

/// Fails unless `len` bytes can be a `width` x `height` RGBA8 image of an accepted size (what
/// [`from_rgba8`] checks before it converts anything).
pub fn check_rgba8(width: usize, height: usize, len: usize) -> Result<()> {
    check_size("image", width, height)?;
    let expected = width * height * 4;
    if len != expected {
        return Err(Error::LengthMismatch {
            what: "RGBA pixel data",
            expected,
            actual: len,
        });
    }
    Ok(())
}

/// Converts a value in 0..1 to a byte, rounding to nearest and clamping out-of-range values.
#[inline]
#[must_use]
pub fn to_byte(v: f32) -> u8 {
    // NaN maps to 0 through the saturating cast.
    (v * 255.0 + 0.5).clamp(0.0, 255.0) as u8
}

/// Writes the image as RGBA8 into `out`, which must hold exactly `width * height * 4` bytes.
pub fn write_rgba8(image: &Image, out: &mut [u8]) -> Result<()> {
    let expected = image.pixel_count() * 4;
    if out.len() != expected {
        return Err(Error::LengthMismatch {
            what: "output pixel buffer",
            expected,
            actual: out.len(),
        });
    }
    let c = image.channels();
    for (src, dst) in image.data().chunks_exact(c).zip(out.chunks_exact_mut(4)) {
        let (r, g, b, a) = match c {
            1 => (src[0], src[0], src[0], 1.0),
            2 => (src[0], src[0], src[0], src[1]),
            3 => (src[0], src[1], src[2], 1.0),
            _ => (src[0], src[1], src[2], src[3]),
        };
        dst.copy_from_slice(&[to_byte(r), to_byte(g), to_byte(b), to_byte(a)]);
    }
    Ok(())
}

/// The image as a new RGBA8 buffer.
#[must_use]
pub fn to_rgba8(image: &Image) -> Vec<u8> {
    let mut out = vec![0; image.pixel_count() * 4];
    write_rgba8(image, &mut out).expect("buffer has the right length by construction");
    out
}

/// Encodes the image as an 8-bit PNG with its own channel count (grey, grey-alpha, RGB or RGBA).
pub fn encode_png(image: &Image) -> Result<Vec<u8>> {
    use image::ImageEncoder;
    use image::codecs::png::PngEncoder;
    let bytes: Vec<u8> = image.data().iter().map(|&v| to_byte(v)).collect();
    let (w, h) = (image.width() as u32, image.height() as u32);
    let layout = match image.channels() {
        1 => image::ExtendedColorType::L8,
        2 => image::ExtendedColorType::La8,
        3 => image::ExtendedColorType::Rgb8,
        _ => image::ExtendedColorType::Rgba8,
    };
    // The PNG encoder directly (not `DynamicImage::write_to`, whose every-format dispatch adds
    // to the wasm package).
    let mut out = Vec::new();
    PngEncoder::new(&mut out)
        .write_image(&bytes, w, h, layout)
        .map_err(|e| Error::Encode(e.to_string()))?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn test_image(channels: usize) -> Image {
        Image::from_fn(7, 5, channels, |x, y, c| {
            ((x * 37 + y * 11 + c * 53) % 256) as f32 / 255.0
        })
        .unwrap()
    }

    #[test]
    fn png_round_trip_is_exact_for_every_channel_count() {
        for channels in [1, 3, 4] {
            let mut img = test_image(channels);
            if channels == 4 {
                img.pixel_mut(0, 0)[3] = 0.5; // keep it transparent so alpha survives
            }
            let decoded = decode(&encode_png(&img).unwrap()).unwrap();
            assert_eq!(decoded.channels(), channels);
            assert_eq!(to_rgba8(&decoded), to_rgba8(&img), "channels {channels}");
        }
    }

    #[test]
    fn jpeg_decodes_close_to_the_original() {
        let img = Image::from_fn(
            32,
            16,
            3,
            |x, _, c| if c == 0 { x as f32 / 31.0 } else { 0.5 },
        )
        .unwrap();
        let rgb: Vec<u8> = img.data().iter().map(|&v| to_byte(v)).collect();
        let mut jpeg = Vec::new();
        image::RgbImage::from_raw(32, 16, rgb)
            .unwrap()
            .write_to(&mut Cursor::new(&mut jpeg), ImageFormat::Jpeg)
            .unwrap();
        let decoded = decode(&jpeg).unwrap();
        assert_eq!((decoded.width(), decoded.height()), (32, 16));
        let err: f32 = decoded
            .data()
            .iter()
            .zip(img.data())
            .map(|(a, b)| (a - b).abs())
            .sum::<f32>()
            / img.data().len() as f32;
        assert!(err < 0.03, "mean abs error {err}");
    }

    #[test]
    fn sample_textures_decode() {
        let bytes = std::fs::read(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/www/samples/brick_64.png"
        ))
        .unwrap();
        let img = decode(&bytes).unwrap();
        assert_eq!((img.width(), img.height(), img.channels()), (64, 64, 1));
    }

    #[test]
    fn bad_bytes_are_named_errors() {
        assert_eq!(decode(&[]).unwrap_err(), Error::EmptyInput);
        let junk = decode(b"hello, this is not an image")
            .unwrap_err()
            .to_string();
        assert!(junk.contains("not a PNG or JPEG"), "{junk}");
        let png = encode_png(&test_image(3)).unwrap();
        let truncated = decode(&png[..png.len() / 2]).unwrap_err().to_string();
        assert!(truncated.starts_with("could not decode"), "{truncated}");
    }

    #[test]
    fn forged_huge_header_is_refused_before_allocating() {
        let mut png = encode_png(&test_image(1)).unwrap();
        // IHDR data starts at byte 16: width then height, big-endian. The CRC no longer matches,
        // which some decoders ignore; either way the answer must be an error, not an allocation.
        png[16..20].copy_from_slice(&100_000u32.to_be_bytes());
        png[20..24].copy_from_slice(&100_000u32.to_be_bytes());
        let msg = decode(&png).unwrap_err().to_string();
        assert!(
            msg.contains("100000") || msg.contains("could not decode"),
            "{msg}"
        );
    }

    #[test]
    fn rgba8_input_picks_channels_and_checks_length() {
        let grey = from_rgba8(1, 2, &[9, 9, 9, 255, 200, 200, 200, 255]).unwrap();
        assert_eq!(grey.channels(), 1);
        let colour = from_rgba8(1, 1, &[9, 8, 7, 255]).unwrap();
        assert_eq!(colour.channels(), 3);
        let alpha = from_rgba8(1, 1, &[9, 8, 7, 100]).unwrap();
        assert_eq!(alpha.channels(), 4);
        assert_eq!(to_rgba8(&alpha), vec![9, 8, 7, 100]);
        let err = from_rgba8(2, 2, &[0; 15]).unwrap_err();
        assert_eq!(
            err,
            Error::LengthMismatch {
                what: "RGBA pixel data",
                expected: 16,
                actual: 15
            }
        );
        assert!(from_rgba8(0, 0, &[]).is_err());
    }

    #[test]
    fn write_rgba8_clamps_and_checks_length() {
        let img = Image::from_vec(1, 1, 3, vec![-0.5, 2.0, f32::NAN]).unwrap();
        let mut out = [0u8; 4];
        write_rgba8(&img, &mut out).unwrap();
        assert_eq!(out, [0, 255, 0, 255]);
        assert!(write_rgba8(&img, &mut [0u8; 3]).is_err());
    }
}
