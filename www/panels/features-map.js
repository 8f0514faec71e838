// The exemplar's feature map of the "Feature-guided" panel, wherever it is detected: on the page
// for an exemplar up to PAGE_DETECT_PIXELS, so that painting shows at once; in the page's worker
// for a photo used whole (its detection takes 13.5 s for 4000x3000, too long to hold the main
// thread). Either way the panel draws it, paints and erases it, starts the synthesis from it as
// edited, and scores outputs against it (broken features), through the same few calls.
import { FeatureMap } from '../pkg/texsynth.js';
import { drawInto, drawOverlay } from '../lib/canvas.js';
import { remoteSession } from '../lib/worker.js';

/** The largest exemplar (in pixels) whose feature map is detected on the page. */
export const PAGE_DETECT_PIXELS = 512 * 512;

/**
 * The view size of a `width` x `height` exemplar whose longer side is shown `side` device pixels
 * long: a larger exemplar's map is drawn that size, each view pixel showing a curve of its
 * footprint (FeatureMap.scaledView), so that one-pixel curves stay visible (the browser's
 * scaling of a larger view would drop most of them).
 */
function viewSize(width, height, side) {
  const scale = Math.min(1, side / Math.max(width, height));
  return { width: Math.max(1, Math.round(width * scale)), height: Math.max(1, Math.round(height * scale)) };
}

/** The exemplar drawn at the view's size (once per map: a photo's pixels are 48 MB). */
function exemplarView(exemplar, view) {
  const full = document.createElement('canvas');
  drawInto(full, exemplar);
  const out = document.createElement('canvas');
  out.width = view.width;
  out.height = view.height;
  const ctx = out.getContext('2d');
  ctx.imageSmoothingQuality = 'high';
  ctx.drawImage(full, 0, 0, view.width, view.height);
  return out;
}

/**
 * Draws an RGBA feature view of `width` x `height` (curves opaque, the rest transparent) on
 * `canvas` at its view size for `side` device pixels: each view pixel shows a curve pixel of its
 * footprint, as FeatureMap.scaledView does for a map (the synthesised map of a 256x256 output
 * shown 140 pixels wide lost every other curve pixel to the browser's scaling).
 */
export function drawCurves(canvas, rgba, width, height, side) {
  const view = viewSize(width, height, side);
  const out = new ImageData(view.width, view.height);
  for (let ty = 0; ty < view.height; ty++) {
    const y0 = Math.floor((ty * height) / view.height);
    const y1 = Math.min(height, Math.max(y0 + 1, Math.floor(((ty + 1) * height) / view.height)));
    for (let tx = 0; tx < view.width; tx++) {
      const x0 = Math.floor((tx * width) / view.width);
      const x1 = Math.min(width, Math.max(x0 + 1, Math.floor(((tx + 1) * width) / view.width)));
      search: for (let y = y0; y < y1; y++) {
        for (let x = x0; x < x1; x++) {
          const i = (y * width + x) * 4;
          if (rgba[i + 3]) {
            out.data.set(rgba.subarray(i, i + 4), (ty * view.width + tx) * 4);
            break search;
          }
        }
      }
    }
  }
  canvas.width = view.width;
  canvas.height = view.height;
  canvas.getContext('2d').putImageData(out, 0, 0);
}

/**
 * Detects the map of `exemplar` with `options` ({ features, threshold }), on the page or in the
 * worker by its size, to be shown `viewSide` device pixels long. Resolves to { width, height,
 * count, here, draw(canvas), stroke(...), synthesis(options, spec), seams(session),
 * broken(session), free() }.
 */
export async function detectExemplarMap(exemplar, options, viewSide) {
  const { width, height } = exemplar;
  const here = width * height <= PAGE_DETECT_PIXELS;
  const view = viewSize(width, height, viewSide);
  const backdrop = exemplarView(exemplar, view);
  const local = here ? new FeatureMap(exemplar, options) : null;
  const remote = here ? null : await remoteSession('FeatureMap', [exemplar, options], { getters: ['count'] });
  let overlay = null;
  const fetchOverlay = async () => {
    if (here) {
      overlay = local.scaledView(view.width, view.height);
      return;
    }
    overlay = await remote.send('scaledView', view.width, view.height);
    await remote.refresh();
  };
  await fetchOverlay();
  // Strokes go to the worker in order; the view is fetched again after the last one in flight.
  let inFlight = 0;
  let onDrawn = null;

  const map = {
    width,
    height,
    here,
    get count() { return here ? local.count : remote.getter('count'); },

    /** The exemplar dimmed, with its curves coloured by orientation bucket. */
    draw(canvas) {
      canvas.width = view.width;
      canvas.height = view.height;
      const ctx = canvas.getContext('2d');
      ctx.drawImage(backdrop, 0, 0);
      ctx.fillStyle = 'rgba(0,0,0,0.45)';
      ctx.fillRect(0, 0, canvas.width, canvas.height);
      drawOverlay(canvas, view.width, view.height, new ImageData(overlay, view.width, view.height));
    },

    /**
     * Paints (`on`) or erases the stroke from (x0, y0) to (x1, y1), in map pixels, with a disc of
     * `radius`; `drawn()` is called once the view shows it (at once on the page).
     */
    stroke(x0, y0, x1, y1, radius, on, drawn) {
      if (here) {
        local.paintLine(x0, y0, x1, y1, radius, on);
        fetchOverlay();
        drawn();
        return Promise.resolve();
      }
      onDrawn = drawn;
      inFlight++;
      return remote.send('paintLine', x0, y0, x1, y1, radius, on).then(async () => {
        if (--inFlight > 0) return;
        await fetchOverlay();
        if (inFlight === 0) onDrawn?.();
      });
    },

    /**
     * The FeatureSynthesis of `exemplar` in the worker, guided by this map as edited: its mask
     * sent along (a small map), or the worker's map itself by reference (a photo's).
     */
    synthesis(synthesisOptions, spec) {
      if (here) {
        return remoteSession('FeatureSynthesis', [exemplar, { ...synthesisOptions, featureMask: local.toMask() }], spec);
      }
      return remoteSession('FeatureSynthesis.withFeatureMap', [exemplar, remote, synthesisOptions], spec);
    },

    /**
     * The count at seams of a graph-cut session of the worker against this map as edited: a
     * photo's map stays in the worker (passed by reference), a small one goes as its mask.
     */
    async seams(session) {
      if (here) return session.send('carriedBrokenFeatures', local.toMask());
      return session.send('carriedBrokenFeaturesOf', remote);
    },

    /** The broken-feature count of a session's output against the exemplar as detected. */
    async broken(session) {
      const rgba = new Uint8ClampedArray(session.width * session.height * 4);
      session.renderInto(rgba);
      if (here) return local.brokenFeatures(rgba, session.width, session.height);
      return remote.send('brokenFeatures', rgba, session.width, session.height);
    },

    free() {
      local?.free();
      remote?.free();
    },
  };
  return map;
}
