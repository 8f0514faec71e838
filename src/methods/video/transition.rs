//! Finding the best transition for a loop (section 7.A, after Schödl et al. 2000): every pair of
//! frames is compared by the SSD over the whole frame, and the loop jumps from just before frame
//! i back to frame j where frames i and j look most alike. The seam window of `2h + 1` frames is
//! centred on the transition, so the pair must leave h frames on either side of both frames.

use super::volume::Volume;
use crate::core::{Error, Result};

/// A chosen transition: the loop plays frames j .. i - 1 and then j again; the seam surface is
/// found in a window of `2 * half_window + 1` frames around it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Transition {
    pub from: usize,
    pub to: usize,
    pub half_window: usize,
    /// Mean squared difference per channel between frames `from` and `to`.
    pub distance: f64,
}

impl Transition {
    /// The loop length i - j.
    #[must_use]
    pub fn period(&self) -> usize {
        self.from - self.to
    }
}

/// The half window for a clip of `frames` frames and a window option of `window` frames: at most
/// (window - 1) / 2, and at most (frames - 1) / 6 so that a range of loop lengths (from 2h + 1 to
/// frames - 2h - 1) remains to choose the best transition from.
#[must_use]
pub fn half_window(frames: usize, window: usize) -> usize {
    ((window.max(1) - 1) / 2).min(frames.saturating_sub(1) / 6)
}

/// The pair (i, j), j < i, of smallest frame SSD among those whose window fits: j >= h,
/// i + h < frames (copy A reaches the frame after the window), i - j >= 2h + 1.
pub fn best_transition(clip: &Volume, window: usize) -> Result<Transition> {
    let n = clip.frames();
    let h = half_window(n, window);
    if h == 0 {
        return Err(Error::InvalidParameter {
            name: "video clip",
            reason: format!(
                "mode 'loop' needs at least 7 frames to find a transition; the clip has {n}"
            ),
        });
    }
    let mut best: Option<Transition> = None;
    for to in h..n {
        for from in (to + 2 * h + 1)..(n - h) {
            let distance = clip.frame_difference(from, to);
            if best.is_none_or(|b| distance < b.distance) {
                best = Some(Transition {
                    from,
                    to,
                    half_window: h,
                    distance,
                });
            }
        }
    }
    best.ok_or_else(|| Error::InvalidParameter {
        name: "video clip",
        reason: format!(
            "no transition with a {}-frame window fits {n} frames",
            2 * h + 1
        ),
    })
}
