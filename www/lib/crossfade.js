// The baseline a video loop is measured against: the clip's first `length` frames, with its
// first few frames cross-faded from the frames that follow the loop's end, so that the last
// frame runs into the first without a jump in content but with a ghosted blend. Graph-cut
// loops (Kwatra et al. 2003, 7.A) cut instead of blending; the page plays both side by side.

/** The cross-fade frames: at most a third of the loop, and at most 8. */
export const fadeFrames = (length) => Math.min(8, Math.floor(length / 3));

/**
 * A loop of `length` frames from `frames` (ImageData, at least `length + 1` of them; with fewer,
 * as many as fit): frame i < F is the blend of frames[length + i] and frames[i], the latter
 * weighing (i + 1) / (F + 1); later frames are the clip's own.
 */
export function crossfadeLoop(frames, length) {
  const n = Math.min(length, frames.length - 1);
  if (n < 2) return frames.slice();
  const fade = fadeFrames(n);
  return Array.from({ length: n }, (_, i) => {
    if (i >= fade) return frames[i];
    const a = frames[n + i].data;
    const b = frames[i].data;
    const t = (i + 1) / (fade + 1);
    const out = new ImageData(frames[i].width, frames[i].height);
    for (let k = 0; k < out.data.length; k++) out.data[k] = (1 - t) * a[k] + t * b[k];
    return out;
  });
}
