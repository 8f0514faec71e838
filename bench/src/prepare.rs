//! Turns a folder of textures into the exemplars every method gets: decode (any size), optional
//! centre crop, shrink so the longer side fits, then an 8-bit PNG written to `out/exemplars/`.
//! Every method, native or wasm, starts from that PNG's bytes through texsynth's own decoder, so
//! all of them see exactly the same pixels; the bytes' hash lets the wasm results prove it.

use std::io::Cursor;
use std::path::{Path, PathBuf};

use image::imageops::FilterType;
use image::{ImageReader, Limits, RgbaImage};
use texsynth::core::{Image, decode, encode_png, from_rgba8};

/// Formats the library decodes; other files in the folder are skipped without comment.
const EXTENSIONS: [&str; 3] = ["png", "jpg", "jpeg"];

/// Photos straight from a camera are fine; a forged header asking for more is refused.
const MAX_DECODE_BYTES: u64 = 2 << 30;

pub struct Exemplar {
    /// File stem (with the extension when two files share a stem).
    pub name: String,
    pub source: PathBuf,
    pub original_size: (u32, u32),
    /// The prepared PNG and the FNV-1a hash of its bytes.
    pub png_path: PathBuf,
    pub png_hash: String,
    /// The PNG decoded by texsynth, as the methods get it.
    pub image: Image,
}

/// A file that looked like an image but could not be used.
pub struct Skipped {
    pub source: PathBuf,
    pub reason: String,
}

/// The image files of `dir`, sorted by name (so runs and tables have a stable order).
pub fn list(dir: &Path) -> Result<Vec<PathBuf>, String> {
    let entries =
        std::fs::read_dir(dir).map_err(|e| format!("cannot read folder {}: {e}", dir.display()))?;
    let mut files: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_file() && has_image_extension(p))
        .collect();
    files.sort();
    Ok(files)
}

fn has_image_extension(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| EXTENSIONS.contains(&e.to_ascii_lowercase().as_str()))
}

/// Prepares every file; the ones that fail are returned separately, never a panic.
pub fn prepare_all(
    files: &[PathBuf],
    crop: Option<(usize, usize)>,
    max_side: usize,
    out_dir: &Path,
) -> Result<(Vec<Exemplar>, Vec<Skipped>), String> {
    std::fs::create_dir_all(out_dir)
        .map_err(|e| format!("cannot create {}: {e}", out_dir.display()))?;
    let (mut done, mut skipped) = (Vec::new(), Vec::new());
    for (i, path) in files.iter().enumerate() {
        let stem = path.file_stem().unwrap_or_default().to_string_lossy();
        let clash = files
            .iter()
            .enumerate()
            .any(|(j, p)| j != i && p.file_stem() == path.file_stem());
        let name = if clash {
            path.file_name()
                .unwrap_or_default()
                .to_string_lossy()
                .replace('.', "-")
        } else {
            stem.into_owned()
        };
        match prepare(path, &name, crop, max_side, out_dir) {
            Ok(e) => done.push(e),
            Err(reason) => skipped.push(Skipped {
                source: path.clone(),
                reason,
            }),
        }
    }
    Ok((done, skipped))
}

fn prepare(
    path: &Path,
    name: &str,
    crop: Option<(usize, usize)>,
    max_side: usize,
    out_dir: &Path,
) -> Result<Exemplar, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("cannot read: {e}"))?;
    let mut reader = ImageReader::new(Cursor::new(&bytes))
        .with_guessed_format()
        .map_err(|e| e.to_string())?;
    let mut limits = Limits::no_limits();
    limits.max_alloc = Some(MAX_DECODE_BYTES);
    reader.limits(limits);
    let rgba = reader
        .decode()
        .map_err(|e| format!("cannot decode: {e}"))?
        .into_rgba8();
    let original_size = rgba.dimensions();
    let rgba = shrink(centre_crop(rgba, crop), max_side);

    let image = from_rgba8(rgba.width() as usize, rgba.height() as usize, rgba.as_raw())
        .map_err(|e| e.to_string())?;
    let png = encode_png(&image).map_err(|e| e.to_string())?;
    let png_path = out_dir.join(format!("{name}.png"));
    std::fs::write(&png_path, &png)
        .map_err(|e| format!("cannot write {}: {e}", png_path.display()))?;
    Ok(Exemplar {
        name: name.to_string(),
        source: path.to_path_buf(),
        original_size,
        png_hash: fnv1a(&png),
        // The same decoder (and limits) as the wasm package's Exemplar.fromBytes.
        image: decode(&png).map_err(|e| e.to_string())?,
        png_path,
    })
}

/// The centre `w` x `h` (each clamped to the image).
fn centre_crop(img: RgbaImage, crop: Option<(usize, usize)>) -> RgbaImage {
    let Some((w, h)) = crop else { return img };
    let (w, h) = ((w as u32).min(img.width()), (h as u32).min(img.height()));
    let (x, y) = ((img.width() - w) / 2, (img.height() - h) / 2);
    image::imageops::crop_imm(&img, x, y, w, h).to_image()
}

/// Shrinks so the longer side is at most `max_side` (0: never), keeping the aspect ratio. The
/// triangle filter widens with the shrink factor, so a large photo is averaged, not aliased.
fn shrink(img: RgbaImage, max_side: usize) -> RgbaImage {
    let (w, h) = shrunk_size(img.width(), img.height(), max_side);
    if (w, h) == img.dimensions() {
        return img;
    }
    image::imageops::resize(&img, w, h, FilterType::Triangle)
}

pub fn shrunk_size(w: u32, h: u32, max_side: usize) -> (u32, u32) {
    let longer = w.max(h) as usize;
    if max_side == 0 || longer <= max_side {
        return (w, h);
    }
    let scale = max_side as f64 / longer as f64;
    let fit = |v: u32| ((f64::from(v) * scale).round() as u32).clamp(1, max_side as u32);
    (fit(w), fit(h))
}

/// 32-bit FNV-1a as hex: cheap to compute the same way in JavaScript (scripts/compare_wasm.mjs),
/// enough to tell whether two byte strings are the same.
pub fn fnv1a(bytes: &[u8]) -> String {
    let mut h: u32 = 0x811c_9dc5;
    for &b in bytes {
        h ^= u32::from(b);
        h = h.wrapping_mul(0x0100_0193);
    }
    format!("{h:08x}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shrinking_keeps_the_aspect_and_leaves_small_images_alone() {
        assert_eq!(shrunk_size(128, 64, 256), (128, 64));
        assert_eq!(shrunk_size(4000, 3000, 256), (256, 192));
        assert_eq!(shrunk_size(3000, 4000, 0), (3000, 4000));
        assert_eq!(shrunk_size(5000, 10, 100), (100, 1));
    }

    #[test]
    fn a_folder_of_odd_files_gives_the_usable_images_shrunk() {
        let dir =
            std::env::temp_dir().join(format!("texsynth-bench-prepare-{}", std::process::id()));
        let out = dir.join("out");
        std::fs::create_dir_all(&dir).unwrap();
        // A 600x300 "photo" as JPEG, a grey PNG, a truncated PNG and a text file.
        let photo = image::RgbImage::from_fn(600, 300, |x, y| image::Rgb([x as u8, y as u8, 90]));
        photo.save(dir.join("photo.JPG")).unwrap();
        let grey = image::GrayImage::from_fn(40, 20, |x, _| image::Luma([x as u8 * 5]));
        grey.save(dir.join("grey.png")).unwrap();
        let png = std::fs::read(dir.join("grey.png")).unwrap();
        std::fs::write(dir.join("broken.png"), &png[..png.len() / 2]).unwrap();
        std::fs::write(dir.join("notes.txt"), "not an image").unwrap();

        let files = list(&dir).unwrap();
        assert_eq!(files.len(), 3, "the text file is not listed");
        let (done, skipped) = prepare_all(&files, Some((500, 400)), 100, &out).unwrap();
        assert_eq!(skipped.len(), 1);
        assert!(skipped[0].source.ends_with("broken.png"));
        let names: Vec<&str> = done.iter().map(|e| e.name.as_str()).collect();
        assert_eq!(names, ["grey", "photo"]);
        // Grey stays one channel and its size (the crop is larger than it); the photo is cropped
        // to 500x300, then shrunk to fit 100.
        assert_eq!(
            (
                done[0].image.width(),
                done[0].image.height(),
                done[0].image.channels()
            ),
            (40, 20, 1)
        );
        assert_eq!((done[1].image.width(), done[1].image.height()), (100, 60));
        assert_eq!(done[1].original_size, (600, 300));
        // What the methods get is exactly the PNG on disk.
        let bytes = std::fs::read(&done[1].png_path).unwrap();
        assert_eq!(fnv1a(&bytes), done[1].png_hash);
        assert_eq!(decode(&bytes).unwrap(), done[1].image);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn fnv1a_matches_the_reference_values() {
        assert_eq!(fnv1a(b""), "811c9dc5");
        assert_eq!(fnv1a(b"a"), "e40c292c");
    }
}
