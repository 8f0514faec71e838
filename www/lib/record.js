// Recording an animation as a WebM video with the browser's MediaRecorder: the frames are played
// on a canvas at a fixed rate while its captured stream is recorded, so the video plays at that
// rate however long each frame took to synthesise.

/** The first WebM codec this browser can record. */
function webmType() {
  const types = ['video/webm;codecs=vp9', 'video/webm;codecs=vp8', 'video/webm'];
  const type = types.find((t) => window.MediaRecorder?.isTypeSupported(t));
  if (!type) throw new Error('this browser cannot record WebM video (no MediaRecorder support)');
  return type;
}

/**
 * Plays `frames` (ImageData) on `canvas` at `fps` with `show(canvas, frame)` and records them.
 * Resolves with the WebM Blob.
 */
export function recordFrames(canvas, frames, fps, show) {
  const mimeType = webmType();
  // A stream that takes a video frame only when asked, so every animation frame lands once.
  const stream = canvas.captureStream(0);
  const [track] = stream.getVideoTracks();
  const recorder = new MediaRecorder(stream, { mimeType, videoBitsPerSecond: 4_000_000 });
  const chunks = [];
  recorder.ondataavailable = (event) => event.data.size > 0 && chunks.push(event.data);
  return new Promise((resolve, reject) => {
    recorder.onerror = (event) => reject(event.error ?? new Error('recording failed'));
    recorder.onstop = () => {
      track.stop();
      resolve(new Blob(chunks, { type: 'video/webm' }));
    };
    recorder.start();
    let i = 0;
    const next = () => {
      if (i === frames.length) {
        recorder.stop();
        return;
      }
      show(canvas, frames[i++]);
      track.requestFrame?.();
      setTimeout(next, 1000 / fps);
    };
    next();
  });
}

/**
 * The "Record WebM" button of a panel: records `frames` on `canvas` (shown with `show`), offers
 * the video on `link` (its text from `describe(blob)`), and marks the page for the tests
 * (`data-recorded-bytes`, `data-recorded-type`). The button says "recording…" meanwhile. Errors
 * are the caller's to show.
 */
export async function recordToLink({ canvas, frames, fps, show, button, link, describe }) {
  button.disabled = true;
  button.textContent = 'recording…';
  try {
    const blob = await recordFrames(canvas, frames, fps, show);
    if (link.href) URL.revokeObjectURL(link.href);
    link.href = URL.createObjectURL(blob);
    link.textContent = describe(blob);
    link.hidden = false;
    document.body.dataset.recordedBytes = String(blob.size);
    document.body.dataset.recordedType = blob.type;
    return blob;
  } finally {
    button.disabled = false;
    button.textContent = 'Record WebM';
  }
}
