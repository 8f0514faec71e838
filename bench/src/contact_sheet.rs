//! One PNG per exemplar: the exemplar, then each method's output (first seed) in the order of
//! the table, each at its real size (so the exemplar's scale is visible) under a caption.

use std::path::Path;

use image::RgbImage;
use texsynth::core::{Image, to_rgba8};

use crate::font;

const BACKGROUND: [u8; 3] = [32, 32, 32];
const INK: [u8; 3] = [235, 235, 235];
const DIM_INK: [u8; 3] = [170, 170, 170];
const FAILED: [u8; 3] = [90, 30, 30];
const MARGIN: usize = 16;
/// Scale of the title and the method names; the figures use scale 1.
const BIG: usize = 2;
const LINE_GAP: usize = 4;

/// One picture of the sheet: `image` None means the method failed (drawn as a dark red square).
pub struct Tile<'a> {
    pub label: String,
    pub note: String,
    pub image: Option<&'a Image>,
}

pub fn write(
    path: &Path,
    title: &str,
    tiles: &[Tile],
    failed_size: (usize, usize),
) -> Result<(), String> {
    let sheet = render(title, tiles, failed_size);
    sheet
        .save(path)
        .map_err(|e| format!("cannot write {}: {e}", path.display()))
}

pub fn render(title: &str, tiles: &[Tile], failed_size: (usize, usize)) -> RgbImage {
    let size = |t: &Tile| t.image.map_or(failed_size, |i| (i.width(), i.height()));
    let caption_h = font::HEIGHT * BIG + LINE_GAP + font::HEIGHT + LINE_GAP;
    let title_h = font::HEIGHT * BIG + 2 * LINE_GAP;
    let widths: Vec<usize> = tiles
        .iter()
        .map(|t| {
            size(t)
                .0
                .max(font::text_width(&t.label) * BIG)
                .max(font::text_width(&t.note))
        })
        .collect();
    let image_h = tiles.iter().map(|t| size(t).1).max().unwrap_or(0);
    let width = MARGIN + widths.iter().map(|w| w + MARGIN).sum::<usize>();
    let width = width.max(2 * MARGIN + font::text_width(title) * BIG);
    let height = MARGIN + title_h + caption_h + image_h + MARGIN;

    let mut sheet = RgbImage::from_pixel(width as u32, height as u32, image::Rgb(BACKGROUND));
    text(&mut sheet, MARGIN, MARGIN, title, BIG, INK);
    let mut x = MARGIN;
    let top = MARGIN + title_h;
    for (tile, w) in tiles.iter().zip(&widths) {
        text(&mut sheet, x, top, &tile.label, BIG, INK);
        text(
            &mut sheet,
            x,
            top + font::HEIGHT * BIG + LINE_GAP,
            &tile.note,
            1,
            DIM_INK,
        );
        let y = top + caption_h;
        match tile.image {
            Some(img) => blit(&mut sheet, x, y, img),
            None => fill(&mut sheet, x, y, failed_size, FAILED),
        }
        x += w + MARGIN;
    }
    sheet
}

/// Draws `image` opaque (any alpha is dropped: the sheet is for judging the pixels).
fn blit(sheet: &mut RgbImage, x0: usize, y0: usize, image: &Image) {
    let rgba = to_rgba8(image);
    for (i, px) in rgba.chunks_exact(4).enumerate() {
        let (x, y) = (x0 + i % image.width(), y0 + i / image.width());
        sheet.put_pixel(x as u32, y as u32, image::Rgb([px[0], px[1], px[2]]));
    }
}

fn fill(sheet: &mut RgbImage, x0: usize, y0: usize, (w, h): (usize, usize), colour: [u8; 3]) {
    for y in y0..y0 + h {
        for x in x0..x0 + w {
            sheet.put_pixel(x as u32, y as u32, image::Rgb(colour));
        }
    }
}

/// Draws `s` with its top-left at (x0, y0), each font pixel `scale` x `scale`; clipped at the edge.
fn text(sheet: &mut RgbImage, x0: usize, y0: usize, s: &str, scale: usize, colour: [u8; 3]) {
    for (i, c) in s.chars().enumerate() {
        for fy in 0..font::HEIGHT {
            for fx in 0..font::WIDTH {
                if !font::ink(c, fx, fy) {
                    continue;
                }
                for dy in 0..scale {
                    for dx in 0..scale {
                        let x = x0 + (i * font::ADVANCE + fx) * scale + dx;
                        let y = y0 + fy * scale + dy;
                        if x < sheet.width() as usize && y < sheet.height() as usize {
                            sheet.put_pixel(x as u32, y as u32, image::Rgb(colour));
                        }
                    }
                }
            }
        }
    }
}
