//! The images patches are copied from: the exemplar, and (section 6.A) its rotated, mirrored and
//! scaled versions, each with the gradient magnitudes the cost M' (eq. 5) divides by.

use super::options::Transforms;
use crate::core::gradient::gradients;
use crate::core::sample::resize_bilinear;
use crate::core::{Edge, Image, Result};

/// One source image.
#[derive(Debug, Clone)]
pub struct Source {
    pub image: Image,
    /// |dI/dx| and |dI/dy| per pixel (norm over channels), for the gradient-scaled cost.
    pub grad_x: Vec<f32>,
    pub grad_y: Vec<f32>,
    /// Scale relative to the exemplar (1 for the exemplar, its rotations and mirrors).
    pub scale: f32,
    /// What this source is, for the teaching views ("exemplar", "rotate 90", "scale 0.5", ...).
    pub name: String,
    /// Which of the synthesis's exemplars it comes from (0 with one exemplar).
    pub exemplar: u32,
}

impl Source {
    #[must_use]
    pub fn new(image: Image, scale: f32, name: impl Into<String>) -> Source {
        let (dx, dy) = gradients(&image, Edge::Clamp);
        let norm = |g: &Image| {
            g.data()
                .chunks_exact(g.channels())
                .map(|p| p.iter().map(|v| v * v).sum::<f32>().sqrt())
                .collect()
        };
        Source {
            grad_x: norm(&dx),
            grad_y: norm(&dy),
            image,
            scale,
            name: name.into(),
            exemplar: 0,
        }
    }

    #[must_use]
    pub fn width(&self) -> usize {
        self.image.width()
    }

    #[must_use]
    pub fn height(&self) -> usize {
        self.image.height()
    }
}

/// The exemplar rotated by 90 degrees clockwise.
#[must_use]
pub fn rotate90(image: &Image) -> Image {
    let (w, h) = (image.width(), image.height());
    Image::from_fn(h, w, image.channels(), |x, y, c| {
        image.pixel(y, h - 1 - x)[c]
    })
    .expect("same pixel count")
}

/// Mirrored left-right (`horizontal`) or top-bottom.
#[must_use]
pub fn mirror(image: &Image, horizontal: bool) -> Image {
    let (w, h) = (image.width(), image.height());
    Image::from_fn(w, h, image.channels(), |x, y, c| {
        if horizontal {
            image.pixel(w - 1 - x, y)[c]
        } else {
            image.pixel(x, h - 1 - y)[c]
        }
    })
    .expect("same size")
}

/// The sources for `exemplar` and `transforms`: the exemplar first, then its transformed versions.
pub fn build_sources(exemplar: &Image, transforms: &Transforms) -> Result<Vec<Source>> {
    let mut sources = vec![Source::new(exemplar.clone(), 1.0, "exemplar")];
    if transforms.rotate {
        let r90 = rotate90(exemplar);
        let r180 = rotate90(&r90);
        let r270 = rotate90(&r180);
        sources.push(Source::new(r90, 1.0, "rotate 90"));
        sources.push(Source::new(r180, 1.0, "rotate 180"));
        sources.push(Source::new(r270, 1.0, "rotate 270"));
    }
    if transforms.mirror {
        sources.push(Source::new(
            mirror(exemplar, true),
            1.0,
            "mirror left-right",
        ));
        sources.push(Source::new(
            mirror(exemplar, false),
            1.0,
            "mirror top-bottom",
        ));
    }
    for &scale in transforms.scales.iter().flatten() {
        let (w, h) = (
            ((exemplar.width() as f32 * scale).round() as usize).max(1),
            ((exemplar.height() as f32 * scale).round() as usize).max(1),
        );
        // Shrinking by more than 2 aliases with plain bilinear sampling: blur first.
        let base = if scale < 0.5 {
            crate::core::pyramid::downsample(exemplar, Edge::Clamp)
        } else {
            exemplar.clone()
        };
        sources.push(Source::new(
            resize_bilinear(&base, w, h, Edge::Clamp)?,
            scale,
            format!("scale {scale}"),
        ));
    }
    Ok(sources)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn four_rotations_and_two_mirrors_are_identities() {
        let img = Image::from_fn(5, 3, 2, |x, y, c| (x * 10 + y * 100 + c) as f32).unwrap();
        let r = rotate90(&img);
        assert_eq!((r.width(), r.height()), (3, 5));
        assert_eq!(r.pixel(2, 0), img.pixel(0, 0)); // top-left goes to top-right
        assert_eq!(rotate90(&rotate90(&rotate90(&r))), img);
        assert_eq!(mirror(&mirror(&img, true), true), img);
        assert_eq!(mirror(&img, false).pixel(0, 0), img.pixel(0, 2));
    }

    #[test]
    fn sources_follow_the_transforms() {
        let img = Image::from_fn(16, 12, 1, |x, y, _| (x + y) as f32).unwrap();
        let t = Transforms {
            rotate: true,
            mirror: true,
            scales: [Some(0.5), Some(2.0), None, None],
            perspective: false,
        };
        let sources = build_sources(&img, &t).unwrap();
        let names: Vec<&str> = sources.iter().map(|s| s.name.as_str()).collect();
        assert_eq!(
            names,
            [
                "exemplar",
                "rotate 90",
                "rotate 180",
                "rotate 270",
                "mirror left-right",
                "mirror top-bottom",
                "scale 0.5",
                "scale 2"
            ]
        );
        assert_eq!((sources[6].width(), sources[6].height()), (8, 6));
        assert_eq!((sources[7].width(), sources[7].height()), (32, 24));
        assert!(sources[0].grad_x.iter().all(|&g| (g - 1.0).abs() < 1e-6));
    }
}
