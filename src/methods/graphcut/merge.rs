//! Interactive merging (section 6.B): several source images placed by the user, some output
//! pixels constrained by a brush to come from a particular source, and the seams between the
//! sources found by the same graph cut that places texture patches. Each step lays the next
//! source over the composite so far (one alpha-expansion move), so a page can show every seam
//! appear.

use super::canvas::{Canvas, Patch, UNCOVERED};
use super::options::Options;
use super::source::Source;
use super::synthesis::Synthesis;
use crate::core::{Error, Image, Result, Rng};
use crate::solvers::fft_ssd::SsdSearch;

/// What one step of a merge did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MergeEvent {
    /// The source laid down by this step; `None` when every source was already down.
    pub source: Option<usize>,
    /// Cost of this step's min cut (0 when no source was laid down).
    pub cut_cost: f64,
    /// Whether every source is down.
    pub done: bool,
}

/// A merge in progress.
pub struct Merge {
    synthesis: Synthesis,
    offsets: Vec<(i32, i32)>,
    /// Per output pixel: 0 = free, k = must come from source k - 1.
    constraints: Vec<u8>,
    next: usize,
}

impl Merge {
    /// `sources` with their top-left positions in a `width` x `height` output, and the brush
    /// constraints (one byte per output pixel: 0 free, k from source k - 1). Sources must share
    /// a channel count (convert first).
    pub fn new(
        width: usize,
        height: usize,
        sources: Vec<(Image, i32, i32)>,
        constraints: Vec<u8>,
        gradient_cost: bool,
    ) -> Result<Merge> {
        if sources.is_empty() || sources.len() > 8 {
            return Err(Error::InvalidParameter {
                name: "sources",
                reason: format!("give 1 to 8 sources, got {}", sources.len()),
            });
        }
        if constraints.len() != width * height {
            return Err(Error::LengthMismatch {
                what: "constraint mask",
                expected: width * height,
                actual: constraints.len(),
            });
        }
        if let Some(bad) = constraints.iter().find(|&&c| c as usize > sources.len()) {
            return Err(Error::InvalidParameter {
                name: "constraints",
                reason: format!("value {bad} names no source (there are {})", sources.len()),
            });
        }
        check_paint(width, height, &sources, &constraints)?;
        let channels = sources
            .iter()
            .map(|(img, _, _)| img.channels())
            .max()
            .expect("non-empty");
        let options = Options {
            output_width: width,
            output_height: height,
            gradient_cost,
            ..Options::default()
        };
        let canvas = Canvas::new(width, height, channels, false)?;
        let mut built = Vec::with_capacity(sources.len());
        let mut offsets = Vec::with_capacity(sources.len());
        for (k, (image, x, y)) in sources.into_iter().enumerate() {
            let (w, h) = (i64::from(x), i64::from(y));
            if w + image.width() as i64 <= 0
                || h + image.height() as i64 <= 0
                || w >= width as i64
                || h >= height as i64
            {
                return Err(Error::InvalidParameter {
                    name: "sources",
                    reason: format!(
                        "source {k} at ({x}, {y}) lies outside the {width}x{height} output"
                    ),
                });
            }
            built.push(Source::new(
                image.with_channels(channels)?,
                1.0,
                format!("source {k}"),
            ));
            offsets.push((x, y));
        }
        let synthesis = Synthesis {
            sigma: 1.0,
            rng: Rng::new(0),
            options,
            sources: built,
            canvas,
            used: Default::default(),
            ssd: SsdSearch::new(),
            seam_features: Vec::new(),
            seam_feature_weight: 0.0,
            // The user placed every source: each is laid down whole.
            max_source_side: usize::MAX,
            windows: Vec::new(),
            graph: Default::default(),
            record_anatomy: false,
            last_graph: None,
        };
        Ok(Merge {
            synthesis,
            offsets,
            constraints,
            next: 0,
        })
    }

    /// The sources and the canvas (composite, labels, seams) of the merge so far.
    #[must_use]
    pub fn synthesis(&self) -> &Synthesis {
        &self.synthesis
    }

    /// Whether every source is down.
    #[must_use]
    pub fn is_done(&self) -> bool {
        self.next >= self.offsets.len()
    }

    /// Records (or stops recording) each step's seam graph for the page's graph view: the
    /// painted pixels are its constraint nodes (held to the composite, or to the new source).
    pub fn set_anatomy(&mut self, on: bool) {
        self.synthesis.record_anatomy = on;
        if !on {
            self.synthesis.last_graph = None;
        }
    }

    /// The seam graph of the last step (recorded while the anatomy is on).
    #[must_use]
    pub fn placement_graph(&self) -> Option<&super::anatomy::GraphView> {
        self.synthesis.last_graph.as_ref()
    }

    /// Lays the next source down with its graph-cut seam.
    pub fn step(&mut self) -> Result<MergeEvent> {
        if self.is_done() {
            return Ok(MergeEvent {
                source: None,
                cut_cost: 0.0,
                done: true,
            });
        }
        let k = self.next;
        let (tx, ty) = self.offsets[k];
        let patch = Patch::new(k as u32, tx, ty);
        let mut force_new = Vec::new();
        let mut keep_old = Vec::new();
        for (i, &c) in self.constraints.iter().enumerate() {
            match c as usize {
                0 => {}
                c if c == k + 1 => force_new.push(i),
                c if c <= k => keep_old.push(i),
                _ => {} // a later source will take it
            }
        }
        let placed = self.synthesis.place(patch, &force_new, &keep_old)?;
        self.next += 1;
        Ok(MergeEvent {
            source: Some(k),
            cut_cost: placed.cut_cost,
            done: self.is_done(),
        })
    }

    /// Which source each output pixel shows (-1 where none does).
    #[must_use]
    pub fn source_map(&self) -> Vec<i32> {
        self.synthesis
            .canvas
            .label
            .iter()
            .map(|&l| {
                if l == UNCOVERED {
                    -1
                } else {
                    self.synthesis.canvas.patches[l as usize].source as i32
                }
            })
            .collect()
    }
}

/// Refuses paint a merge could not honour, by the pixel and source it names: a pixel painted for
/// a source that does not cover it, and a pixel painted for source k on the edge of k's
/// rectangle where an earlier source covers the pixel and its neighbour beyond the edge (the
/// seam graph holds such a pixel to the composite, so k could not take it).
fn check_paint(
    width: usize,
    height: usize,
    sources: &[(Image, i32, i32)],
    constraints: &[u8],
) -> Result<()> {
    let inside = |k: usize, x: i64, y: i64| {
        let (image, sx, sy) = &sources[k];
        let (sx, sy) = (i64::from(*sx), i64::from(*sy));
        (sx..sx + image.width() as i64).contains(&x) && (sy..sy + image.height() as i64).contains(&y)
    };
    let in_output = |x: i64, y: i64| (0..width as i64).contains(&x) && (0..height as i64).contains(&y);
    let covered_before = |k: usize, x: i64, y: i64| (0..k).any(|j| inside(j, x, y));
    for (i, &c) in constraints.iter().enumerate() {
        if c == 0 {
            continue;
        }
        let k = c as usize - 1;
        let (x, y) = ((i % width) as i64, (i / width) as i64);
        if !inside(k, x, y) {
            return Err(Error::InvalidParameter {
                name: "constraints",
                reason: format!("pixel ({x}, {y}) is painted for source {k}, which does not cover it"),
            });
        }
        let held = covered_before(k, x, y)
            && [(1, 0), (-1, 0), (0, 1), (0, -1)].iter().any(|&(dx, dy)| {
                let (nx, ny) = (x + dx, y + dy);
                in_output(nx, ny) && !inside(k, nx, ny) && covered_before(k, nx, ny)
            });
        if held {
            return Err(Error::InvalidParameter {
                name: "constraints",
                reason: format!(
                    "pixel ({x}, {y}) is painted for source {k} on the edge of that source, where an earlier source lies on both sides: the seam cannot reach it; paint a pixel further inside"
                ),
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::super::anatomy::NodeKind;
    use super::*;

    #[test]
    fn painted_pixels_come_from_their_source_and_the_seam_runs_between() {
        // Two different images side by side with a wide overlap: paint the left edge for the
        // first and the right edge for the second; the cut must honour both.
        let a = Image::from_fn(
            40,
            30,
            3,
            |x, _, c| if c == 0 { 0.2 + x as f32 / 100.0 } else { 0.3 },
        )
        .unwrap();
        let b = Image::from_fn(
            40,
            30,
            3,
            |_, y, c| if c == 1 { 0.2 + y as f32 / 100.0 } else { 0.6 },
        )
        .unwrap();
        let (w, h) = (60, 30);
        let mut constraints = vec![0u8; w * h];
        for y in 0..h {
            for x in 0..4 {
                constraints[y * w + x] = 1;
                constraints[y * w + w - 1 - x] = 2;
            }
            constraints[y * w + 25] = 1; // inside the overlap: must stay with the first source
        }
        let mut merge = Merge::new(
            w,
            h,
            vec![(a, 0, 0), (b, 20, 0)],
            constraints.clone(),
            false,
        )
        .unwrap();
        assert_eq!(merge.step().unwrap().source, Some(0));
        let second = merge.step().unwrap();
        let (k, cut) = (second.source.unwrap(), second.cut_cost);
        assert_eq!(k, 1);
        assert!(cut > 0.0);
        assert!(merge.is_done() && merge.step().unwrap().source.is_none());
        let map = merge.source_map();
        for (i, &c) in constraints.iter().enumerate() {
            if c > 0 {
                assert_eq!(map[i], i32::from(c) - 1, "pixel {i}");
            }
        }
        assert!(
            map.iter().all(|&s| s >= 0),
            "the two sources cover the output"
        );
        // Every row switches from source 0 to source 1 somewhere in the overlap.
        for y in 0..h {
            let row = &map[y * w..(y + 1) * w];
            assert!(row[..20].iter().all(|&s| s == 0) && row[40..].iter().all(|&s| s == 1));
        }
    }

    #[test]
    fn bad_merges_are_named_errors() {
        let img = Image::new(10, 10, 1).unwrap();
        assert!(
            Merge::new(20, 20, vec![], vec![0; 400], false)
                .err()
                .unwrap()
                .to_string()
                .contains("sources")
        );
        assert!(
            Merge::new(20, 20, vec![(img.clone(), 0, 0)], vec![0; 10], false)
                .err()
                .unwrap()
                .to_string()
                .contains("constraint mask")
        );
        assert!(
            Merge::new(20, 20, vec![(img.clone(), 0, 0)], vec![3; 400], false)
                .err()
                .unwrap()
                .to_string()
                .contains("names no source")
        );
        // Paint for a source that does not cover the pixel.
        let mut paint = vec![0u8; 400];
        paint[15] = 1;
        let err = Merge::new(20, 20, vec![(img.clone(), 0, 0)], paint, false)
            .err()
            .unwrap()
            .to_string();
        assert!(err.contains("(15, 0)") && err.contains("does not cover"), "{err}");
        // Paint for the second source on its left edge, with the first source on both sides.
        let mut paint = vec![0u8; 400];
        paint[5 * 20 + 5] = 2;
        let two = vec![(img.clone(), 0, 0), (img.clone(), 5, 0)];
        let err = Merge::new(20, 20, two.clone(), paint, false)
            .err()
            .unwrap()
            .to_string();
        assert!(err.contains("(5, 5)") && err.contains("edge"), "{err}");
        // One pixel further inside, the paint is kept.
        let mut paint = vec![0u8; 400];
        paint[5 * 20 + 6] = 2;
        let mut merge = Merge::new(20, 20, two, paint, false).unwrap();
        while !merge.is_done() {
            merge.step().unwrap();
        }
        assert_eq!(merge.source_map()[5 * 20 + 6], 1);
        assert!(
            Merge::new(20, 20, vec![(img, 30, 0)], vec![0; 400], false)
                .err()
                .unwrap()
                .to_string()
                .contains("outside")
        );
    }

    /// The graph view of a merge step shows the paint as constraint nodes: pixels painted for
    /// the composite so far held to it, pixels painted for the new source held to that, and the
    /// cut between them.
    #[test]
    fn the_graph_view_shows_the_paint_as_constraint_nodes() {
        let a = Image::from_fn(40, 30, 3, |x, _, _| x as f32 / 40.0).unwrap();
        let b = Image::from_fn(40, 30, 3, |_, y, _| y as f32 / 30.0).unwrap();
        let (w, h) = (60, 30);
        let mut constraints = vec![0u8; w * h];
        for y in 5..25 {
            constraints[y * w + 24] = 1; // in the overlap, for the first source
            constraints[y * w + 34] = 2; // in the overlap, for the second
        }
        let mut merge = Merge::new(w, h, vec![(a, 0, 0), (b, 20, 0)], constraints, false).unwrap();
        merge.set_anatomy(true);
        merge.step().unwrap();
        merge.step().unwrap();
        let g = merge.placement_graph().expect("recorded").clone();
        // The second source's box starts at x = 20.
        assert_eq!((g.x, g.y, g.width, g.height), (20, 0, 40, 30));
        let kind = |x: usize, y: usize| g.kind[y * g.width + x - 20];
        let taken = |x: usize, y: usize| g.taken[y * g.width + x - 20] == 1;
        for y in 5..25 {
            assert_eq!(kind(24, y), NodeKind::KeepOld as u8, "row {y}");
            assert_eq!(kind(34, y), NodeKind::TakeNew as u8, "row {y}");
            assert!(!taken(24, y) && taken(34, y), "row {y}");
        }
        // Beyond the first source nothing was covered: those pixels take the new one, no node.
        assert_eq!(kind(45, 10), NodeKind::New as u8);
        merge.set_anatomy(false);
        assert!(merge.placement_graph().is_none());
    }
}
