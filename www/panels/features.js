// The "Feature-guided" panel (Wu & Yu 2004): the exemplar's feature map (threshold, paint and
// erase), the synthesis placing patches live with its own feature map beside it, the current
// patch's context region, correspondences and warp grid, and plain graph-cut textures run on the
// same exemplar and seed for comparison, with the broken-feature count of each.
// Both syntheses run in the page's worker (www/lib/worker.js); the exemplar's map is detected and
// edited on the page, or in the worker for a photo used whole (features-map.js), and guides the
// synthesis as edited.
import { drawInto, shownRect } from '../lib/canvas.js';
import { showQualityOrWhy } from '../lib/quality.js';
import { explain } from '../lib/explain.js';
import { paintable } from '../lib/keyboard-brush.js';
import { remoteSession } from '../lib/worker.js';
import { ANATOMY_HTML, showPlacementAnatomy } from './graphcut-anatomy.js';
import { detectExemplarMap, drawCurves, PAGE_DETECT_PIXELS } from './features-map.js';

export const id = 'features';
export const title = 'Feature-guided';

const WARP_TITLE = 'bend each patch so its features meet the placed ones (section 2.2)';
const ANATOMY_TITLE = 'graph-cut placement: each placement\'s colour-cost surface, the probabilities it was drawn by (colour plus feature cost) and its seam graph';

const OPTIONS_HTML = `
  <label title="which curves make the feature map">features <select id="fg-kind" class="view">
    <option value="ridges">ridges (thin lines)</option><option value="edges">edges</option><option value="both">both</option></select></label>
  <label title="percentile of the responses above which a pixel is a strong feature">threshold
    <input id="fg-threshold" class="view" type="range" min="0.75" max="0.98" step="0.01" value="0.9"> <span id="fg-threshold-value">0.90</span></label>
  <label title="graph cut: whole-exemplar patches, offsets and seams guided by the features (few seams); scan: the paper's patches in scan order, warped">placement <select id="fg-placement"><option value="graphcut" selected>graph cut</option><option value="scan">scan (paper)</option></select></label>
  <label title="patch side (the paper: 32 to 64)">patch <input id="fg-patch" type="number" value="64" min="16" max="128"></label>
  <label id="fg-warp-label" title="${WARP_TITLE}"><input id="fg-warp" type="checkbox" checked> warp</label>
  <label><input id="fg-compare" type="checkbox" checked> compare with graph cut</label>
  <label id="fg-anatomy-label" title="${ANATOMY_TITLE}"><input id="fg-anatomy-on" type="checkbox"> placement anatomy</label>
  <span class="views">exemplar map:
    <label><input type="radio" name="fg-brush" class="view" value="off" checked> view</label>
    <label><input type="radio" name="fg-brush" class="view" value="paint"> paint</label>
    <label><input type="radio" name="fg-brush" class="view" value="erase"> erase</label></span>`;

const SIDE_HTML = `
  <div class="readout" id="fg-readout">press Run or Step</div>
  <div class="explain" id="fg-explain" data-history-text aria-live="polite"></div>
  <div class="side-row">
    <figure><canvas id="fg-exemplar" class="paintable" aria-label="Exemplar feature map"></canvas><figcaption id="fg-exemplar-caption">exemplar features</figcaption></figure>
    <figure><canvas id="fg-map" aria-label="Synthesised feature map"></canvas><figcaption>synthesised feature map</figcaption></figure>
  </div>
  <figure><canvas id="fg-graphcut" aria-label="Plain graph cut, same seed"></canvas><figcaption id="fg-graphcut-caption">plain graph cut, same exemplar and seed</figcaption></figure>
  <p class="quality" id="fg-quality"></p>
  <p class="legend">On the output: the patch (white), its context region (yellow), each correspondence as a line
  from where the partner feature lay to where the warp moved it (cyan), and the warp as a deformed grid.
  Feature colours give the orientation bucket.</p>
  ${ANATOMY_HTML.replace('C(t), eq. 2', 'colour cost C(t), eq. 2; the feature cost re-ranks its best')
    .replace('Right: the chance eq. 3 gives each (bright: likely).',
      'Right: the chance eq. 3 gives each of the best offsets by colour, from colour plus feature cost (section 3; the rest cannot be drawn).')}`;

/** The longer side `canvas` is shown at, in device pixels (the maps' boxes are 140 CSS pixels). */
function shownSide(canvas) {
  const box = canvas.getBoundingClientRect();
  return Math.round(Math.max(box.width, box.height, 64) * (window.devicePixelRatio || 1));
}

export function createPanel(ui) {
  let map = null;
  let mapOf = null;
  let synthesis = null;
  let graphcut = null;
  let pending = null;
  let painting = false;
  let oursBroken = Promise.resolve({ detected: null, seams: null });
  // With the placement anatomy on (graph-cut placement), each step also brings back the
  // placement's cost surface and seam graph (recorded by the session only when asked).
  // The scan placement warps its patches (section 2.2); graph-cut placement does not.
  const featuresKey = () => (ui.$('fg-placement').value === 'graphcut' ? 'fg-hybrid' : 'fg-features');
  const anatomyOn = () => ui.$('fg-anatomy-on').checked && ui.$('fg-placement').value === 'graphcut';
  const FEATURE_VIEWS = () => ({
    views: ['renderInto', 'renderFeaturesInto'],
    calls: anatomyOn() ? ['placement', 'placementCosts', 'placementGraph'] : ['placement'],
  });

  // Each placement has a control the other lacks: the warp bends the scan placement's patches
  // (section 2.2), and graph-cut placement lays whole-exemplar patches unbent; the placement
  // anatomy shows graph-cut placement's draw. A control that would do nothing is turned off
  // and its tooltip says why (a checked warp box under graph-cut placement read "warp: None"
  // after every patch, with no reason given).
  function syncPlacementControls() {
    const scan = ui.$('fg-placement').value === 'scan';
    ui.$('fg-warp').disabled = !scan;
    ui.$('fg-warp-label').title = scan ? WARP_TITLE
      : `${WARP_TITLE}: the scan placement's patches only; graph-cut placement lays whole-exemplar patches unbent`;
    ui.$('fg-anatomy-on').disabled = scan;
    ui.$('fg-anatomy-label').title = scan ? `${ANATOMY_TITLE} (not for the scan placement)` : ANATOMY_TITLE;
  }

  const detectOptions = () => ({ features: ui.$('fg-kind').value, threshold: Number(ui.$('fg-threshold').value) });
  let detecting = null;
  let mapOptions = null;
  let lastPaint = null;
  let detectError = null;

  /**
   * Detects the exemplar's map (on the page, or in the worker for a photo: features-map.js) and
   * draws it; resolves to the map, or null when detection failed or a newer one superseded it.
   */
  function detect() {
    map?.free();
    map = null;
    detectError = null;
    mapOf = ui.exemplar();
    const { width, height } = mapOf;
    const caption = ui.$('fg-exemplar-caption');
    caption.dataset.mapReady = 'false';
    const job = detectExemplarMap(mapOf, detectOptions(), shownSide(ui.$('fg-exemplar'))).then((m) => {
      if (detecting !== job) {
        m.free();
        return null;
      }
      map = m;
      drawExemplarMap();
      return m;
    }, (error) => {
      if (detecting !== job) return null;
      detectError = error?.message ?? String(error);
      caption.textContent = `exemplar ${width}×${height}: features not detected (${detectError}); the synthesis detects its own`;
      return null;
    });
    detecting = job;
    mapOptions = JSON.stringify(detectOptions());
    if (width * height > PAGE_DETECT_PIXELS) {
      // A photo: shown at once, its curves once the worker has found them.
      drawInto(ui.$('fg-exemplar'), mapOf);
      caption.textContent = `exemplar ${width}×${height}: detecting its features in the worker (seconds for a photo)…`;
      caption.dataset.detectedHere = 'false';
    }
    return job;
  }

  /** The map of the current exemplar and options: detected again only when one of them changed. */
  function ensureMap() {
    const same = detecting && mapOf === ui.exemplar() && mapOptions === JSON.stringify(detectOptions());
    return same ? detecting : detect();
  }

  function drawExemplarMap() {
    map.draw(ui.$('fg-exemplar'));
    const caption = ui.$('fg-exemplar-caption');
    caption.textContent = `exemplar features: ${map.count} pixels` +
      (map.here ? '' : ` (the ${map.width}×${map.height} photo's map, detected and edited in the worker)`);
    caption.dataset.detectedHere = String(map.here);
    caption.dataset.mapReady = 'true';
  }

  /**
   * A brush move on the exemplar's map: a stroke from the last point (no gaps however fast the
   * pointer). The brush is 0.6 map pixels to paint (curves stay one pixel wide) and 2.5 screen
   * pixels, at least 2.5 map pixels, to erase (on a photo's map a screen pixel is many).
   */
  function paintAt(event, start) {
    const mode = document.querySelector('input[name="fg-brush"]:checked').value;
    if (mode === 'off' || !map) return;
    // The map as shown: the canvas's box with the picture contained in it (object-fit), so a
    // map of another shape than the square box keeps its proportions.
    const box = shownRect(ui.$('fg-exemplar'));
    if (!(box.width > 0 && box.height > 0)) return;
    const x = ((event.clientX - box.left) / box.width) * map.width;
    const y = ((event.clientY - box.top) / box.height) * map.height;
    const from = start || !lastPaint ? [x, y] : lastPaint;
    lastPaint = [x, y];
    const radius = mode === 'paint' ? 0.6 : 2.5 * Math.max(1, map.width / box.width);
    const painted = map;
    map.stroke(from[0], from[1], x, y, radius, mode === 'paint', () => {
      if (map === painted) drawExemplarMap();
    }).catch((error) => {
      if (map === painted) ui.$('fg-exemplar-caption').textContent = `the edit failed: ${error?.message ?? error}`;
    });
    resetSessions();
  }

  /** The readout's warp part: graph-cut placement has none to report. */
  function warpText(event) {
    if (ui.$('fg-placement').value !== 'scan') return 'no warp (graph-cut placement)';
    return `${event.correspondences} correspondences · warp: ${event.warp}`;
  }

  function options() {
    const patchField = ui.$('fg-patch');
    return {
      outputWidth: ui.outputWidth(),
      outputHeight: ui.outputHeight(),
      seed: ui.seed(),
      placement: ui.$('fg-placement').value,
      // Left at its default, the library fits the patch to an exemplar smaller than 64.
      ...(patchField.value === patchField.defaultValue ? {} : { patchSize: Number(patchField.value) }),
      warp: ui.$('fg-warp').checked,
      // The map as edited goes along with these (see features-map.js); without one (its
      // detection failed) the session detects its own with the same options.
      ...detectOptions(),
    };
  }

  function drawPlacement() {
    const p = synthesis.result('placement');
    const canvas = ui.outputCanvas;
    const ctx = canvas.getContext('2d');
    const s = canvas.width / synthesis.width;
    ctx.save();
    ctx.lineWidth = 1;
    ctx.strokeStyle = 'rgba(255,255,255,0.9)';
    ctx.strokeRect(p.x * s + 0.5, p.y * s + 0.5, p.size * s - 1, p.size * s - 1);
    ctx.fillStyle = 'rgba(255,220,60,0.18)';
    if (p.top) ctx.fillRect(p.x * s, p.y * s, p.size * s, p.top * s);
    if (p.left) ctx.fillRect(p.x * s, (p.y + p.top) * s, p.left * s, (p.size - p.top) * s);
    // The warp as a grid deformed by the displacements (exaggerated 3x so a pixel shows).
    const n = p.grid.length ? Math.ceil(p.size / 4) : 0;
    const at = (i, j) => {
      const k = (j * n + i) * 2;
      return [(p.x + i * 4 + 3 * p.grid[k]) * s, (p.y + j * 4 + 3 * p.grid[k + 1]) * s];
    };
    ctx.strokeStyle = 'rgba(120,255,160,0.5)';
    for (let j = 0; j < n; j++) {
      ctx.beginPath();
      for (let i = 0; i < n; i++) (i ? ctx.lineTo : ctx.moveTo).apply(ctx, at(i, j));
      ctx.stroke();
    }
    for (let i = 0; i < n; i++) {
      ctx.beginPath();
      for (let j = 0; j < n; j++) (j ? ctx.lineTo : ctx.moveTo).apply(ctx, at(i, j));
      ctx.stroke();
    }
    ctx.strokeStyle = 'rgba(80,230,255,0.95)';
    for (let k = 0; k < p.pairs.length; k += 4) {
      ctx.beginPath();
      ctx.moveTo(p.pairs[k + 2] * s, p.pairs[k + 3] * s);
      ctx.lineTo(p.pairs[k] * s, p.pairs[k + 1] * s);
      ctx.stroke();
    }
    ctx.restore();
  }

  function zoomCanvas() {
    // Draw the output 2x so the teaching overlay is legible.
    const canvas = ui.outputCanvas;
    const src = document.createElement('canvas');
    drawInto(src, synthesis);
    canvas.width = synthesis.width * 2;
    canvas.height = synthesis.height * 2;
    const ctx = canvas.getContext('2d');
    ctx.imageSmoothingEnabled = false;
    ctx.drawImage(src, 0, 0, canvas.width, canvas.height);
  }

  /**
   * The session's two broken-feature counts, or nulls where there is no map (its detection
   * failed): `detected`, on a map detected on the output against the exemplar's as detected;
   * `seams`, on the carried (synthesised) map against the map it carries, the curves its seams
   * cut (feature-guided synthesis grows that map; graph cut's is made from its canvas with the
   * same map's mask). Both lower is better.
   */
  async function broken(session, kind) {
    if (!map) return { detected: null, seams: null };
    const detected = map.broken(session);
    const seams = kind === 'features' ? session.send('carriedBrokenFeatures') : map.seams(session);
    return { detected: await detected, seams: await seams };
  }

  const brokenText = (b) => (b === null ? `not measured (${detectError ?? 'no feature map'})` : b.toFixed(1));
  const countsText = ({ detected, seams }) => (detected === null ? brokenText(null)
    : `${brokenText(detected)}, at seams ${brokenText(seams)}`);

  function resetSessions() {
    synthesis?.free();
    synthesis = null;
    graphcut?.free();
    graphcut = null;
    pending = null;
    delete document.body.dataset.featuresDone;
  }

  /** Makes (once) the session `make()` resolves to; null when a reset came in between. */
  async function made(make) {
    pending ??= make();
    const current = pending;
    const session = await current;
    if (pending !== current) {
      session.free();
      return null;
    }
    pending = null;
    return session;
  }

  return {
    id,
    title,
    optionsHtml: OPTIONS_HTML,
    sideHtml: SIDE_HTML,
    mount() {
      const ex = ui.$('fg-exemplar');
      ex.onpointerdown = (e) => { painting = true; paintAt(e, true); };
      ex.onpointermove = (e) => painting && paintAt(e, false);
      this.onPointerUp = () => { painting = false; };
      window.addEventListener('pointerup', this.onPointerUp);
      paintable(ex, 'Edit the feature map');
      ui.$('fg-threshold').addEventListener('input', () => {
        ui.$('fg-threshold-value').textContent = Number(ui.$('fg-threshold').value).toFixed(2);
      });
      syncPlacementControls();
      ui.$('fg-placement').addEventListener('change', () => {
        syncPlacementControls();
        ui.$('gc-anatomy').hidden = !anatomyOn();
      });
      // The anatomy is recorded from the session's start: toggling it starts over.
      ui.$('fg-anatomy-on').addEventListener('change', () => {
        ui.$('gc-anatomy').hidden = !anatomyOn();
        resetSessions();
      });
      for (const id of ['fg-threshold', 'fg-kind']) {
        ui.$(id).addEventListener('change', () => { detect(); resetSessions(); });
      }
    },
    unmount() {
      window.removeEventListener('pointerup', this.onPointerUp);
      resetSessions();
      // A detection still running frees its map when it ends (see detect).
      detecting = null;
      map?.free();
      map = null;
    },
    async step() {
      ensureMap();
      if (!synthesis) {
        // The constructor indexes the exemplar's features: seconds for a photo, whose map the
        // worker may still be detecting.
        const { width, height } = ui.exemplar();
        ui.$('fg-readout').textContent = `setting up: the feature index of the ${width}×${height} exemplar` +
          (map ? '' : ' (its features are being detected: a photo takes several seconds)');
        const guide = await detecting;
        try {
          synthesis = await made(() => (guide
            ? guide.synthesis(options(), FEATURE_VIEWS)
            : remoteSession('FeatureSynthesis', [ui.exemplar(), options()], FEATURE_VIEWS)));
        } catch (error) {
          // A new exemplar or threshold freed the map while the session was being made.
          if (guide && guide !== map) return null;
          throw error;
        }
        if (!synthesis) return null;
        if (anatomyOn()) await synthesis.send('setAnatomy', true);
      }
      const compare = ui.$('fg-compare').checked;
      if (!synthesis.done) {
        const current = synthesis;
        const event = await current.step();
        if (synthesis !== current) return null; // reset while the step ran
        // The run goes on to the comparison, so only the last event of both is `done`.
        return { ...event, phase: 'features', featuresDone: event.done, done: event.done && !compare };
      }
      if (!compare) return null;
      if (!graphcut) {
        const options = { outputWidth: ui.outputWidth(), outputHeight: ui.outputHeight(), seed: ui.seed() };
        graphcut = await made(() => remoteSession('GraphcutTextures', [ui.exemplar(), options], { views: ['renderInto'] }));
        if (!graphcut) return null;
      }
      if (graphcut.done) return null;
      const current = graphcut;
      const event = await current.step();
      if (graphcut !== current) return null;
      return { ...event, phase: 'graphcut' };
    },
    onStep(event) {
      explain(ui.$('fg-explain'), event.phase === 'features' ? featuresKey() : 'fg-graphcut');
      if (event.phase === 'features') {
        zoomCanvas();
        drawPlacement();
        // The transferred view itself (no copy of an output-sized buffer every step).
        const curves = synthesis.imageData('renderFeaturesInto')?.data ?? (() => {
          const copy = new Uint8ClampedArray(synthesis.width * synthesis.height * 4);
          synthesis.view('renderFeaturesInto', copy);
          return copy;
        })();
        drawCurves(ui.$('fg-map'), curves, synthesis.width, synthesis.height, shownSide(ui.$('fg-map')));
        const how = event.colourOnly ? 'colour only (no oriented features to match)'
          : `feature cost ${event.featureCost.toFixed(2)} · colour ${event.colourCost.toExponential(2)}`;
        ui.$('fg-readout').textContent = `patch ${event.patchesPlaced}/${event.patchesPlanned} from (${event.sourceX}, ${event.sourceY}) · ` +
          `${event.contextFeatures} context features · ${warpText(event)} · ${how}`;
        document.body.dataset.featurePatches = String(event.patchesPlaced);
        if (anatomyOn()) showPlacementAnatomy(ui.$, synthesis.result('placementCosts'), synthesis.result('placementGraph'));
        if (event.featuresDone) {
          const quality = ui.$('fg-quality');
          const scored = synthesis;
          oursBroken = broken(synthesis, 'features');
          Promise.all([oursBroken, showQualityOrWhy(quality, ui.exemplar(), synthesis, () => synthesis === scored)]).then(([b]) => {
            if (synthesis !== scored) return;
            quality.dataset.broken = String(b.detected);
            quality.dataset.brokenSeams = String(b.seams);
            quality.textContent += ` · broken features ${countsText(b)}`;
            if (!ui.$('fg-compare').checked) document.body.dataset.featuresDone = 'true';
          });
        }
      } else {
        drawInto(ui.$('fg-graphcut'), graphcut);
        if (event.done) {
          const scored = graphcut;
          Promise.all([broken(graphcut, 'graphcut'), oursBroken]).then(([b, ours]) => {
            if (graphcut !== scored) return;
            const caption = ui.$('fg-graphcut-caption');
            caption.textContent = `plain graph cut, same exemplar and seed · broken features ${countsText(b)}` +
              (b.detected === null ? '' : ` (feature-guided: ${countsText(ours)}; lower is better)`);
            caption.dataset.broken = String(b.detected);
            caption.dataset.brokenSeams = String(b.seams);
            document.body.dataset.featuresDone = 'true';
          });
        }
      }
    },
    reset() {
      resetSessions();
      if (ui.exemplar()) {
        ensureMap();
        const ctx = ui.outputCanvas.getContext('2d');
        ctx.clearRect(0, 0, ui.outputCanvas.width, ui.outputCanvas.height);
      }
      const readout = ui.$('fg-readout');
      if (readout) readout.textContent = 'press Run or Step';
      explain(ui.$('fg-explain'), featuresKey());
      if (ui.$('fg-quality')) ui.$('fg-quality').textContent = '';
    },
  };
}
