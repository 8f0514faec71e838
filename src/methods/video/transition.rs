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

/// The best transition and up to `count - 1` more good ones within the window around it (the
/// paper's "limited number of good transitions within a window around the transition"): pairs
/// whose frames lie within `h` of the best pair's, each of a loop length of its own (the copies'
/// relative offset is what a seam can differ by), the least frame SSD for each length, best
/// first.
pub fn good_transitions(clip: &Volume, window: usize, count: usize) -> Result<Vec<Transition>> {
    let best = best_transition(clip, window)?;
    let (n, h) = (clip.frames(), best.half_window);
    let mut by_period: Vec<Transition> = Vec::new();
    for to in best.to.saturating_sub(h).max(h)..=(best.to + h).min(n - 1) {
        let last = (best.from + h).min(n - h - 1);
        for from in best.from.saturating_sub(h).max(to + 2 * h + 1)..=last {
            if (from, to) == (best.from, best.to) {
                continue;
            }
            let candidate = Transition {
                from,
                to,
                half_window: h,
                distance: clip.frame_difference(from, to),
            };
            match by_period.iter_mut().find(|t| t.period() == candidate.period()) {
                Some(t) if candidate.distance < t.distance => *t = candidate,
                Some(_) => {}
                None if candidate.period() != best.period() => by_period.push(candidate),
                None => {}
            }
        }
    }
    by_period.sort_by(|a, b| a.distance.total_cmp(&b.distance).then(a.from.cmp(&b.from)));
    by_period.truncate(count.saturating_sub(1));
    by_period.insert(0, best);
    Ok(by_period)
}
