//! The views that show where the seam surface lies: a per-frame overlay and an x-t slice through
//! the volume, in which a temporal seam (the per-pixel transition time of 7.A) is a curve.

use super::canvas::UNCOVERED;
use super::session::Session;
use super::volume::check_frame;
use crate::core::{Error, Result, codec::to_byte};

/// Spatial seams (the labels of x or y neighbours differ) in opaque red.
pub const SPATIAL_SEAM: [u8; 4] = [255, 40, 40, 255];
/// Temporal seams (the voxel's patch differs from the one before it in time) in translucent
/// yellow: where in this frame the video switches patches.
pub const TEMPORAL_SEAM: [u8; 4] = [255, 220, 0, 170];

/// Per-frame seam overlay of output frame `t`: RGBA, transparent where no seam.
pub fn seams_rgba(session: &Session, t: usize, out: &mut [u8]) -> Result<()> {
    let (w, h, d) = session.size();
    check_frame(t, d)?;
    check_len(out, w * h * 4)?;
    let labels = session.frame_labels(t);
    let before = (t > 0).then(|| session.frame_labels(t - 1));
    for (i, o) in out.chunks_exact_mut(4).enumerate() {
        let (x, y) = (i % w, i / w);
        let l = labels[i];
        let differs = |j: usize| l != UNCOVERED && labels[j] != UNCOVERED && labels[j] != l;
        let spatial = (x + 1 < w && differs(i + 1)) || (y + 1 < h && differs(i + w));
        let temporal = before
            .as_ref()
            .is_some_and(|b| l != UNCOVERED && b[i] != UNCOVERED && b[i] != l);
        o.copy_from_slice(if spatial {
            &SPATIAL_SEAM
        } else if temporal {
            &TEMPORAL_SEAM
        } else {
            &[0, 0, 0, 0]
        });
    }
    Ok(())
}

/// The x-t slice at row `y`: `width` x `frames` RGBA (row t is output frame t), with seam voxels
/// (label change along x or t) drawn in red.
pub fn slice_xt_rgba(session: &Session, y: usize, out: &mut [u8]) -> Result<()> {
    let (w, h, d) = session.size();
    if y >= h {
        return Err(Error::InvalidParameter {
            name: "row",
            reason: format!("row {y} does not exist; frames are {h} rows high"),
        });
    }
    check_len(out, w * d * 4)?;
    let mut previous: Option<Vec<u32>> = None;
    for t in 0..d {
        let labels = session.frame_labels(t);
        let frame = session.frame(t);
        for x in 0..w {
            let i = y * w + x;
            let l = labels[i];
            let seam = l != UNCOVERED
                && ((x + 1 < w && labels[i + 1] != UNCOVERED && labels[i + 1] != l)
                    || previous
                        .as_ref()
                        .is_some_and(|p| p[i] != UNCOVERED && p[i] != l));
            let o = &mut out[(t * w + x) * 4..(t * w + x + 1) * 4];
            if seam {
                o.copy_from_slice(&SPATIAL_SEAM);
            } else {
                let c = &frame[i * 3..i * 3 + 3];
                o.copy_from_slice(&[to_byte(c[0]), to_byte(c[1]), to_byte(c[2]), 255]);
            }
        }
        previous = Some(labels);
    }
    Ok(())
}

/// Output frame `t` as opaque RGBA.
pub fn frame_rgba(session: &Session, t: usize, out: &mut [u8]) -> Result<()> {
    let (w, h, d) = session.size();
    check_frame(t, d)?;
    check_len(out, w * h * 4)?;
    for (o, c) in out
        .chunks_exact_mut(4)
        .zip(session.frame(t).chunks_exact(3))
    {
        o.copy_from_slice(&[to_byte(c[0]), to_byte(c[1]), to_byte(c[2]), 255]);
    }
    Ok(())
}

fn check_len(out: &[u8], expected: usize) -> Result<()> {
    if out.len() == expected {
        Ok(())
    } else {
        Err(Error::LengthMismatch {
            what: "target RGBA array",
            expected,
            actual: out.len(),
        })
    }
}
