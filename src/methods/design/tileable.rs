//! Cyclic (tileable) textures, Shen et al. 2009, section 4 and Fig. 7: cut the image open along a
//! line, so that its old left and right edges meet inside it; stitch them with a graph cut over
//! an overlap of m_h columns; the new outer edges were neighbours in the image, so the result
//! tiles horizontally. Then the same vertically over m_v rows, with the cut's graph wrapping
//! around horizontally so that the first step's seamless wrap survives the second.
//!
//! One change to the paper's steps: it cuts at w/2; we cut at the column, within the middle half,
//! whose two sides differ least (the paper: "cut the tube along an arbitrary vertical line"), so
//! that the new wrap-around edge is as seamless as the texture allows.

use super::deform::transpose;
use crate::core::{Error, Image, Result};
use crate::methods::graphcut::cost::colour_distance;
use crate::solvers::maxflow::{Graph, HARD_CONSTRAINT};

/// The overlaps of the two stitches.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct TileableOptions {
    /// m_h: columns the halves overlap. Default (None): a sixth of the width, at most 64.
    pub overlap_x: Option<usize>,
    /// m_v: rows the halves overlap. Default (None): a sixth of the height, at most 64.
    pub overlap_y: Option<usize>,
    /// The memory budget in MiB (see `crate::core::budget`); `None`: the default, 1024.
    pub memory_budget_mib: Option<usize>,
}

/// The smallest side that can be made tileable.
pub const MIN_SIDE: usize = 16;

/// A cyclic texture and how it was made.
#[derive(Debug, Clone, PartialEq)]
pub struct Tileable {
    /// `(w - m_h) x (h - m_v)`, seamless across its wrap-around edges.
    pub image: Image,
    /// Where the image was cut open (column, then row of the horizontally stitched image).
    pub cut_x: usize,
    /// The row where the horizontally stitched image was cut open (`cut_x` is the column).
    pub cut_y: usize,
    /// Cost of each stitch's minimum cut (sum of M over the seam).
    pub seam_cost_x: f64,
    /// Cost of the vertical stitch's minimum cut (`seam_cost_x` is the horizontal one's).
    pub seam_cost_y: f64,
    /// Per output pixel: true on a pixel next to either seam (for display).
    pub seam: Vec<bool>,
}

/// Most columns (rows) an overlap takes by default. The seam has room enough in 64 pixels, and
/// the cut's cost grows with the overlap: at 1024x1024 an overlap of a sixth of the side (170)
/// takes 526 ms against 134 ms for 64, with seams no more costly (66 + 64 against 62 + 85).
pub const DEFAULT_MAX_OVERLAP: usize = 64;

fn overlap(len: usize, asked: Option<usize>, name: &'static str) -> Result<usize> {
    let max = len / 4 - 1;
    let m = asked.unwrap_or((len / 6).clamp(2, max.min(DEFAULT_MAX_OVERLAP)));
    if m < 2 || m > max {
        return Err(Error::InvalidParameter {
            name,
            reason: format!("must be between 2 and {max} for a side of {len} pixels, got {m}"),
        });
    }
    Ok(m)
}

/// Which stitch a step made.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TileableEvent {
    /// False for the horizontal stitch (steps 1-2), true for the vertical one (steps 3-4).
    pub vertical: bool,
    /// Where the image was cut open.
    pub cut: usize,
    /// Cost of this stitch's minimum cut (sum of M over the seam).
    pub seam_cost: f64,
    /// True once both stitches are made: on the vertical stitch, and on any step after it.
    pub done: bool,
}

/// Making an image tileable in two steps (each a graph cut), so that a page can draw between
/// them: the horizontal stitch, then the vertical one.
pub struct TileableSession {
    input: Image,
    m_h: usize,
    m_v: usize,
    graph: Graph,
    horizontal: Option<(Image, usize, f64, Stitch)>,
    result: Option<Tileable>,
}

impl TileableSession {
    /// Validates the size and the overlaps.
    pub fn new(image: &Image, options: TileableOptions) -> Result<Self> {
        let (w, h) = (image.width(), image.height());
        if w < MIN_SIDE || h < MIN_SIDE {
            return Err(Error::InvalidSize {
                what: "image to make tileable",
                width: w,
                height: h,
                reason: format!("each side must be at least {MIN_SIDE} pixels"),
            });
        }
        let (m_h, m_v) = (
            overlap(w, options.overlap_x, "overlapX")?,
            overlap(h, options.overlap_y, "overlapY")?,
        );
        let budget = options
            .memory_budget_mib
            .unwrap_or(crate::core::budget::DEFAULT_MEMORY_BUDGET_MIB);
        crate::core::budget::validate_budget(budget)?;
        super::memory::tileable_working_set((w, h, image.channels()), (m_h, m_v)).check(
            &format!("image {w}x{h}"),
            super::memory::TILEABLE,
            budget,
        )?;
        Ok(TileableSession {
            m_h,
            m_v,
            input: image.clone(),
            graph: Graph::new(1)?,
            horizontal: None,
            result: None,
        })
    }

    /// Whether both stitches are made.
    #[must_use]
    pub fn is_done(&self) -> bool {
        self.result.is_some()
    }

    /// The estimated working set (see `super::memory`).
    #[must_use]
    pub fn working_set(&self) -> crate::core::budget::WorkingSet {
        let i = &self.input;
        super::memory::tileable_working_set(
            (i.width(), i.height(), i.channels()),
            (self.m_h, self.m_v),
        )
    }

    /// The image as far as it is made: the input, then horizontally stitched, then the result.
    #[must_use]
    pub fn image(&self) -> &Image {
        match (&self.result, &self.horizontal) {
            (Some(t), _) => &t.image,
            (None, Some(h)) => &h.0,
            (None, None) => &self.input,
        }
    }

    /// The finished texture (None until both stitches are made).
    #[must_use]
    pub fn result(&self) -> Option<&Tileable> {
        self.result.as_ref()
    }

    /// Makes the next stitch.
    pub fn step(&mut self) -> Result<TileableEvent> {
        if let Some(t) = &self.result {
            return Ok(TileableEvent {
                vertical: true,
                cut: t.cut_y,
                seam_cost: t.seam_cost_y,
                done: true,
            });
        }
        let Some((horizontal, cut_x, seam_cost_x, seam_x)) = self.horizontal.take() else {
            // Steps 1-2: rearrange as I_h1 | I_h2 and stitch them over m_h columns.
            let made = open_and_stitch(&self.input, self.m_h, false, &mut self.graph)?;
            let event = TileableEvent {
                vertical: false,
                cut: made.1,
                seam_cost: made.2,
                done: false,
            };
            self.horizontal = Some(made);
            return Ok(event);
        };
        // Steps 3-4: the same on rows (on the transpose), wrapping along the first stitch's axis.
        let (vertical, cut_y, seam_cost_y, seam_y) =
            open_and_stitch(&transpose(&horizontal), self.m_v, true, &mut self.graph)?;
        let result = transpose(&vertical);
        let (ow, oh) = (result.width(), result.height());
        // Output pixel (x, y) is the transpose's (y, x), which came from row `source` of the
        // horizontally stitched image.
        let seam = (0..ow * oh)
            .map(|i| {
                let (x, y) = (i % ow, i / ow);
                let t = x * oh + y;
                seam_y.seam[t] || seam_x.seam[seam_y.source[t] * ow + x]
            })
            .collect();
        self.result = Some(Tileable {
            image: result,
            cut_x,
            cut_y,
            seam_cost_x,
            seam_cost_y,
            seam,
        });
        Ok(TileableEvent {
            vertical: true,
            cut: cut_y,
            seam_cost: seam_cost_y,
            done: true,
        })
    }
}

/// Makes `image` tileable (section 4's four steps) in one call.
pub fn make_tileable(image: &Image, options: TileableOptions) -> Result<Tileable> {
    let mut session = TileableSession::new(image, options)?;
    while !session.step()?.done {}
    Ok(session.result.expect("done"))
}

/// Per pixel of a stitched image: the input column it shows, and whether it lies on the seam.
struct Stitch {
    source: Vec<usize>,
    seam: Vec<bool>,
}

/// Cuts `image` open at the best column in its middle half, puts the right part first, and
/// stitches the old right edge to the old left edge over `m` columns. With `wrap_rows` the cut's
/// graph also joins the last row to the first. Returns the image, the cut column, the seam's
/// cost, and where each pixel came from.
fn open_and_stitch(
    image: &Image,
    m: usize,
    wrap_rows: bool,
    graph: &mut Graph,
) -> Result<(Image, usize, f64, Stitch)> {
    let (w, h, c) = (image.width(), image.height(), image.channels());
    let lo = (w / 4).max(m + 1);
    let hi = (3 * w / 4).min(w - m - 1);
    let cut = (lo..=hi)
        .min_by(|&a, &b| {
            let cost = |x: usize| -> f32 {
                (0..h)
                    .map(|y| colour_distance(image.pixel(x - 1, y), image.pixel(x, y)))
                    .sum()
            };
            cost(a).total_cmp(&cost(b))
        })
        .expect("the middle half is not empty for sides of 16 or more");
    // I_h1 = columns cut..w, I_h2 = columns 0..cut. In the result, column x < w - cut - m shows
    // I_h1 only, the m columns after it are the overlap (I_h1's last m columns = image columns
    // w-m..w against I_h2's first m = image columns 0..m), and the rest shows I_h2.
    let first = w - cut;
    let start = first - m;
    let out_w = w - m;
    let n = m * h;
    graph.reset(n)?;
    let a = |k: usize, y: usize| image.pixel(w - m + k, y);
    let b = |k: usize, y: usize| image.pixel(k, y);
    let edge_cost = |k1: usize, y1: usize, k2: usize, y2: usize| -> f32 {
        colour_distance(a(k1, y1), b(k1, y1)) + colour_distance(a(k2, y2), b(k2, y2))
    };
    for y in 0..h {
        for k in 0..m {
            let i = y * m + k;
            if k == 0 {
                graph.add_terminal(i, HARD_CONSTRAINT, 0.0)?;
            }
            if k == m - 1 {
                graph.add_terminal(i, 0.0, HARD_CONSTRAINT)?;
            }
            if k + 1 < m {
                let cost = edge_cost(k, y, k + 1, y);
                graph.add_edge(i, i + 1, cost, cost)?;
            }
            if y + 1 < h || (wrap_rows && h > 1) {
                let y2 = (y + 1) % h;
                let cost = edge_cost(k, y, k, y2);
                graph.add_edge(i, y2 * m + k, cost, cost)?;
            }
        }
    }
    let seam_cost = graph.maxflow();
    let mut data = Vec::with_capacity(out_w * h * c);
    let mut source = Vec::with_capacity(out_w * h);
    let mut seam = vec![false; out_w * h];
    for y in 0..h {
        for x in 0..out_w {
            let column = if x < start {
                cut + x
            } else if x < first {
                let k = x - start;
                let here = graph.is_source_side(y * m + k);
                // A seam pixel: its label differs from its right or lower neighbour's.
                let right = k + 1 < m && graph.is_source_side(y * m + k + 1) != here;
                let down =
                    (y + 1 < h || wrap_rows) && graph.is_source_side((y + 1) % h * m + k) != here;
                seam[y * out_w + x] = right || down;
                if here { w - m + k } else { k }
            } else {
                x - start
            };
            source.push(column);
            data.extend_from_slice(image.pixel(column, y));
        }
    }
    Ok((
        Image::from_vec(out_w, h, c, data)?,
        cut,
        seam_cost,
        Stitch { source, seam },
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::testing::{noise, sample};

    /// Mean colour distance across the wrap-around edges and across the interior edges.
    fn wrap_and_interior(img: &Image) -> (f64, f64) {
        let (w, h) = (img.width(), img.height());
        let d = |a: (usize, usize), b: (usize, usize)| {
            f64::from(colour_distance(img.pixel(a.0, a.1), img.pixel(b.0, b.1)))
        };
        let (mut wrap, mut wn, mut inner, mut inn) = (0.0, 0, 0.0, 0);
        for y in 0..h {
            for x in 0..w {
                let right = d((x, y), ((x + 1) % w, y));
                let down = d((x, y), (x, (y + 1) % h));
                if x + 1 == w {
                    wrap += right;
                    wn += 1;
                } else {
                    inner += right;
                    inn += 1;
                }
                if y + 1 == h {
                    wrap += down;
                    wn += 1;
                } else {
                    inner += down;
                    inn += 1;
                }
            }
        }
        (wrap / f64::from(wn), inner / f64::from(inn))
    }

    #[test]
    fn every_shared_texture_tiles_seamlessly() {
        let names = [
            "ballast", "brick", "carpet", "dirt", "grass", "gravel", "jungle", "paving", "planks",
            "potatoes", "rock", "roof", "sand", "squares", "stone", "tiles",
        ];
        for name in names {
            for size in [64, 128] {
                let img = sample(&format!("{name}_{size}"));
                let (before, _) = wrap_and_interior(&img);
                let t = make_tileable(&img, TileableOptions::default()).unwrap();
                let m = size / 6;
                assert_eq!((t.image.width(), t.image.height()), (size - m, size - m));
                let (wrap, interior) = wrap_and_interior(&t.image);
                assert!(
                    wrap <= interior,
                    "{name}_{size}: wrap {wrap:.4} > interior {interior:.4} (before: {before:.4})"
                );
            }
        }
    }

    #[test]
    fn the_result_is_made_of_the_image_s_own_pixels() {
        let img = noise(40, 32, 3, 1);
        let t = make_tileable(
            &img,
            TileableOptions {
                overlap_x: Some(5),
                overlap_y: Some(4),
                memory_budget_mib: None,
            },
        )
        .unwrap();
        assert_eq!((t.image.width(), t.image.height()), (35, 28));
        let pixels: std::collections::HashSet<Vec<u32>> = (0..32)
            .flat_map(|y| (0..40).map(move |x| (x, y)))
            .map(|(x, y)| img.pixel(x, y).iter().map(|v| v.to_bits()).collect())
            .collect();
        for y in 0..28 {
            for x in 0..35 {
                let p: Vec<u32> = t.image.pixel(x, y).iter().map(|v| v.to_bits()).collect();
                assert!(pixels.contains(&p), "({x}, {y}) is not from the image");
            }
        }
        assert!(t.seam.iter().any(|&s| s));
    }

    #[test]
    fn the_session_stitches_horizontally_then_vertically() {
        let img = noise(48, 40, 3, 3);
        let mut s = TileableSession::new(&img, TileableOptions::default()).unwrap();
        assert_eq!(s.image(), &img);
        let first = s.step().unwrap();
        assert!(!first.vertical && !first.done && !s.is_done());
        assert_eq!((s.image().width(), s.image().height()), (40, 40));
        let second = s.step().unwrap();
        assert!(second.vertical && second.done);
        assert_eq!((s.image().width(), s.image().height()), (40, 34));
        assert_eq!(
            s.step().unwrap(),
            second,
            "stepping after done repeats the last event"
        );
        let once = make_tileable(&img, TileableOptions::default()).unwrap();
        assert_eq!(s.result().unwrap(), &once);
    }

    #[test]
    fn bad_sizes_are_named() {
        let img = noise(12, 40, 3, 2);
        let msg = make_tileable(&img, TileableOptions::default())
            .unwrap_err()
            .to_string();
        assert!(
            msg.contains("12x40") && msg.contains("at least 16"),
            "{msg}"
        );
        let img = noise(40, 40, 3, 2);
        let msg = make_tileable(
            &img,
            TileableOptions {
                overlap_x: Some(30),
                overlap_y: None,
                memory_budget_mib: None,
            },
        )
        .unwrap_err()
        .to_string();
        assert!(
            msg.contains("overlapX") && msg.contains("between 2 and 9"),
            "{msg}"
        );
    }
}
