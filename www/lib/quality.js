// Shows the method-independent quality metrics of a finished output (see the README).
import { measureQuality } from '../pkg/texsynth.js';

/**
 * Outputs larger than this on a side are scored on their central window of this side, so the
 * figures come within a second or so of the run's end: scoring takes 0.6-1 s at 512x512 in
 * wasm, about 3 s at 1024x1024 (graph cut of tiles_128; noisy outputs longer), and a whole
 * 4096x4096 output would need more memory than the budget allows (measureQuality refuses it).
 */
export const QUALITY_MAX_SIDE = 512;

function write(element, q, size) {
  const where = q.window ? ` (of the central ${q.window.width}×${q.window.height} of ${size})` : '';
  element.textContent =
    `quality${where} (lower is better): coherence ${q.coherence.toExponential(2)} · ` +
    `completeness ${q.completeness.toExponential(2)} · histogram ${q.histogram.toExponential(2)} · ` +
    `flat ${(100 * q.flat).toFixed(1)}% (the exemplar itself: about 10%)`;
  element.dataset.coherence = String(q.coherence);
  element.dataset.completeness = String(q.completeness);
  element.dataset.histogram = String(q.histogram);
  element.dataset.flat = String(q.flat);
  if (q.window) element.dataset.window = `${q.window.x},${q.window.y},${q.window.width},${q.window.height}`;
  else delete element.dataset.window;
  delete element.dataset.failed;
}

/**
 * Scores what `session` renders against `exemplar` and writes the figures into `element`. A
 * session in the worker (www/lib/worker.js) is scored there, off the main thread; a local one
 * here, at once. Returns a promise that settles when the figures are shown.
 */
export function showQuality(element, exemplar, session) {
  const size = `${session.width}×${session.height}`;
  if (typeof session.quality === 'function') {
    return session.quality({ maxSide: QUALITY_MAX_SIDE }).then((q) => write(element, q, size));
  }
  const image = new ImageData(session.width, session.height);
  session.renderInto(image.data);
  write(element, measureQuality(exemplar, image.data, session.width, session.height), size);
  return Promise.resolve();
}

/**
 * showQuality, and where scoring fails (a photo used whole as the exemplar passes the memory
 * budget, for one) the reason in `element` instead of the figures, so the panel says why there
 * are none rather than leaving the line empty. Resolves to true when the figures are shown, false
 * when not; a failure after the panel moved on (`isCurrent()` false: a reset freed the session)
 * is dropped.
 */
export function showQualityOrWhy(element, exemplar, session, isCurrent = () => true) {
  return showQuality(element, exemplar, session).then(() => true, (error) => {
    if (isCurrent()) {
      element.textContent = `quality not measured: ${error?.message ?? error}`;
      element.dataset.failed = 'true';
    }
    return false;
  });
}
