// Shows the method-independent quality metrics of a finished output (see the README).
import { measureQuality } from '../pkg/texsynth.js';

/** Scores what `session` renders against `exemplar` and writes the figures into `element`. */
export function showQuality(element, exemplar, session) {
  const image = new ImageData(session.width, session.height);
  session.renderInto(image.data);
  const q = measureQuality(exemplar, image.data, session.width, session.height);
  element.textContent =
    `quality (lower is better): coherence ${q.coherence.toExponential(2)} · ` +
    `completeness ${q.completeness.toExponential(2)} · histogram ${q.histogram.toExponential(2)} · ` +
    `flat ${(100 * q.flat).toFixed(1)}% (the exemplar itself: about 10%)`;
  element.dataset.coherence = String(q.coherence);
  element.dataset.flat = String(q.flat);
}
