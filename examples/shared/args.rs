//! What every numbered example takes: an exemplar (PNG or JPEG) and a folder to write into.

// Not every example uses both helpers.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

/// The first argument (default: the 64x64 tiles sample) decoded, and the folder of the second
/// (default: `target/examples/NAME`), created.
pub fn exemplar_and_folder(
    name: &str,
) -> Result<(texsynth::Image, PathBuf), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let input = args
        .get(1)
        .map_or("www/samples/tiles_64.png", String::as_str);
    let folder = args
        .get(2)
        .map_or_else(|| Path::new("target/examples").join(name), PathBuf::from);
    std::fs::create_dir_all(&folder)?;
    let exemplar = texsynth::decode(&std::fs::read(input).map_err(|e| format!("{input}: {e}"))?)?;
    Ok((exemplar, folder))
}

/// Writes `image` as `folder/file` and says so.
pub fn save(
    folder: &Path,
    file: &str,
    image: &texsynth::Image,
) -> Result<(), Box<dyn std::error::Error>> {
    std::fs::write(folder.join(file), texsynth::encode_png(image)?)?;
    println!(
        "{}: {}x{}",
        folder.join(file).display(),
        image.width(),
        image.height()
    );
    Ok(())
}
