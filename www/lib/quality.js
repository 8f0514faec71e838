// Shows the method-independent quality metrics of a finished output (see the README).
import { measureQuality } from '../pkg/texsynth.js';

function write(element, q) {
  element.textContent =
    `quality (lower is better): coherence ${q.coherence.toExponential(2)} · ` +
    `completeness ${q.completeness.toExponential(2)} · histogram ${q.histogram.toExponential(2)} · ` +
    `flat ${(100 * q.flat).toFixed(1)}% (the exemplar itself: about 10%)`;
  element.dataset.coherence = String(q.coherence);
  element.dataset.completeness = String(q.completeness);
  element.dataset.histogram = String(q.histogram);
  element.dataset.flat = String(q.flat);
}

/**
 * Scores what `session` renders against `exemplar` and writes the figures into `element`. A
 * session in the worker (www/lib/worker.js) is scored there, off the main thread; a local one
 * here, at once. Returns a promise that settles when the figures are shown.
 */
export function showQuality(element, exemplar, session) {
  if (typeof session.quality === 'function') return session.quality().then((q) => write(element, q));
  const image = new ImageData(session.width, session.height);
  session.renderInto(image.data);
  write(element, measureQuality(exemplar, image.data, session.width, session.height));
  return Promise.resolve();
}
