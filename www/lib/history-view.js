// The history scrubber under the output: after every step the page copies what the panel drew
// (its output canvas, or all of a panel's canvases) into a StepHistory; the range input moves
// through the kept steps and puts that step's pixels back on the canvases, the panel's plots get
// a marker on that step, and a strip of thumbnails jumps to the last image of each level. The
// panel's readouts (`#side .readout`, and any element marked `data-history-text`) are kept with
// each step too, so the words beside the picture are that step's. Only canvases and those texts
// are touched, never the session, so scrubbing while paused cannot change the run; the page
// returns to the live view before the next step (see main.js).
import { HISTORY_BUDGET, StepHistory } from './history.js';
import { markPlot, plotLength } from './plot.js';
import { rovingFocus, syncRoving } from './tablist.js';

const MiB = 1024 * 1024;
const TEXTS = '#side .readout, [data-history-text]';

/** Copies of the readouts' contents (copies, so the live nodes and their listeners stay put). */
const copyTexts = () => [...document.querySelectorAll(TEXTS)].map((el) => ({ el, nodes: [...el.childNodes].map((n) => n.cloneNode(true)) }));
const THUMB_HEIGHT = 48;

/** A short name for a step from its event: the method's level and energy where it has them. */
function labelOf(step, event) {
  const parts = [`step ${step}`];
  if (event.energyKind) parts.push(event.energyKind);
  if (event.level != null) parts.push(`level ${event.level + 1}${event.levelCount ? `/${event.levelCount}` : ''}`);
  if (event.method) parts.push(event.method);
  return parts.join(' · ');
}

/** A small picture of the step's `images` (snapshots, see below) side by side, for the strip. */
function thumbnail(images) {
  const widths = images.map((c) => Math.max(1, Math.round((c.width / c.height) * THUMB_HEIGHT)));
  const thumb = document.createElement('canvas');
  thumb.width = widths.reduce((a, b) => a + b, 0) + 2 * (images.length - 1);
  thumb.height = THUMB_HEIGHT;
  // Drawn when the snapshots arrive, off the step's own task.
  Promise.all(images.map((image) => image.ready)).then(() => {
    const ctx = thumb.getContext('2d');
    let x = 0;
    images.forEach((image, k) => {
      if (image.bitmap) ctx.drawImage(image.bitmap, x, 0, widths[k], THUMB_HEIGHT);
      x += widths[k] + 2;
    });
  });
  return thumb;
}

/**
 * Wires the scrubber. `canvases()` gives the canvases a step draws on; `plots()` the plot
 * canvases whose marker should follow; `onScrub()` is called when the user moves away from the
 * live view (the page pauses a running session then).
 */
export function createHistoryView({ range, live, info, strip, canvases, plots, onScrub }) {
  // A dropped step's bitmaps are closed now, or as they arrive.
  const release = (entry) => entry.images.forEach((image) => {
    image.dropped = true;
    image.bitmap?.close();
    image.bitmap = null;
  });
  const history = new StepHistory(HISTORY_BUDGET, release);
  let steps = 0;
  let shown = null; // the entry on the canvases while scrubbing; null: the live view
  let liveImages = null; // what the canvases showed when scrubbing began
  let liveTexts = null; // the readouts' own nodes then

  const drawn = (list) => list.filter((c) => c.width > 0 && c.height > 0);
  const grab = (list) => drawn(list).map((c) => ({ canvas: c, image: c.getContext('2d').getImageData(0, 0, c.width, c.height) }));

  /**
   * What each canvas shows now, kept as an ImageBitmap: the snapshot is taken at the call and
   * costs next to nothing on the main thread, where getImageData on a 1024x1024 canvas takes
   * 6-10 ms per step (it waits for the canvas's drawing and converts every pixel). The bitmap
   * arrives a moment later; `put` draws it then if its step is still shown.
   */
  const snapshot = (list) => drawn(list).map((c) => {
    const image = { width: c.width, height: c.height, bitmap: null, dropped: false };
    // A snapshot that fails leaves its step without a picture rather than an error.
    image.ready = createImageBitmap(c).then((bitmap) => {
      if (image.dropped) bitmap.close();
      else image.bitmap = bitmap;
    }, () => {});
    return { canvas: c, image };
  });

  function put(images) {
    for (const { canvas, image } of images) {
      if (canvas.width !== image.width || canvas.height !== image.height) {
        canvas.width = image.width;
        canvas.height = image.height;
      }
      const ctx = canvas.getContext('2d');
      if (image.data) {
        ctx.putImageData(image, 0, 0);
      } else if (image.bitmap) {
        ctx.save();
        ctx.globalCompositeOperation = 'copy';
        ctx.drawImage(image.bitmap, 0, 0);
        ctx.restore();
      } else {
        const entry = shown;
        image.ready.then(() => shown === entry && image.bitmap && put([{ canvas, image }]));
      }
    }
  }

  function describe() {
    const n = history.entries.length;
    const at = shown ? history.entries.indexOf(shown) : n - 1;
    const entry = history.entries[at];
    const where = n === 0 ? 'no steps yet' : `${shown ? 'showing' : 'live:'} ${entry.label}`;
    info.textContent = `${where} · ${n} step images kept, ${(history.bytes / MiB).toFixed(1)} of ` +
      `${HISTORY_BUDGET / MiB} MiB${history.stride > 1 ? ` (1 step in ${history.stride} and each level's last)` : ''}`;
    range.max = String(Math.max(0, n - 1));
    range.value = String(Math.max(0, at));
    range.disabled = n < 2;
    range.setAttribute('aria-valuetext', n ? entry.label : 'no steps yet');
    live.disabled = !shown;
    document.body.dataset.historyLength = String(n);
    document.body.dataset.historyStep = shown ? String(shown.step) : 'live';
    for (const button of strip.children) {
      button.setAttribute('aria-pressed', String(button.entry === (shown ?? history.entries.at(-1))));
    }
    // The strip is one Tab stop (arrow keys move along it), on the thumbnail shown.
    syncRoving(strip, '.thumb', (b) => b.getAttribute('aria-pressed') === 'true');
  }

  /** The strip's button for `entry`, made once, so a thumbnail that stays keeps its focus. */
  function buttonOf(entry) {
    if (entry.button) return entry.button;
    const button = document.createElement('button');
    button.type = 'button';
    button.className = 'thumb';
    button.entry = entry;
    button.setAttribute('role', 'listitem');
    const short = document.createElement('span');
    short.textContent = entry.levelKey != null ? entry.label.split(' · ').at(-1) : `step ${entry.step}`;
    button.append(entry.thumb, short);
    button.addEventListener('click', () => show(history.entries.indexOf(entry)));
    entry.button = button;
    return button;
  }

  function renderStrip() {
    const newest = history.entries.at(-1);
    const buttons = history.strip().map((entry) => {
      const button = buttonOf(entry);
      const caption = entry.levelEnd ? `${entry.label} (level's last)` : entry === newest ? `${entry.label} (newest)` : entry.label;
      button.setAttribute('aria-label', `Show ${caption}`);
      button.title = caption;
      return button;
    });
    // Only what changed moves: the level ends stay in place while the newest changes each step.
    buttons.forEach((button, i) => {
      if (strip.children[i] !== button) strip.insertBefore(button, strip.children[i] ?? null);
    });
    while (strip.children.length > buttons.length) strip.lastElementChild.remove();
  }

  /** Shows kept step `index` (the newest index is still "scrubbing" until live is pressed). */
  function show(index) {
    const entry = history.entries[index];
    if (!entry) return;
    if (!shown) {
      liveImages = grab(canvases());
      liveTexts = [...document.querySelectorAll(TEXTS)].map((el) => ({ el, nodes: [...el.childNodes] }));
      onScrub?.();
    }
    shown = entry;
    put(entry.images.map((image, k) => ({ canvas: entry.canvases[k], image })));
    for (const { el, nodes } of entry.texts) if (el.isConnected) el.replaceChildren(...nodes.map((n) => n.cloneNode(true)));
    for (const { canvas, length } of entry.plots) markPlot(canvas, length - 1);
    describe();
  }

  /** Back to the live view: the canvases get back what they showed before scrubbing. */
  function goLive({ restore = true } = {}) {
    if (!shown) return;
    if (restore && liveImages) put(liveImages);
    if (restore && liveTexts) for (const { el, nodes } of liveTexts) el.replaceChildren(...nodes);
    for (const { canvas } of shown.plots) markPlot(canvas, null);
    shown = null;
    liveImages = null;
    liveTexts = null;
    describe();
  }

  range.addEventListener('input', () => show(Number(range.value)));
  rovingFocus(strip, '.thumb');
  live.addEventListener('click', () => goLive());

  return {
    history,
    get scrubbing() { return shown !== null; },
    goLive,
    /** Copies what the panel just drew for `event` into the history (called after onStep). */
    capture(event) {
      // A step that was in flight when the user began scrubbing: its drawing is the live view now.
      if (shown) goLive({ restore: false });
      steps += 1;
      const grabbed = snapshot(canvases());
      if (grabbed.length === 0) return;
      const levelKey = event.level == null ? null : `${event.energyKind ?? ''}${event.method ?? ''}:${event.level}`;
      history.add({
        step: steps,
        levelKey,
        label: labelOf(steps, event),
        canvases: grabbed.map((g) => g.canvas),
        images: grabbed.map((g) => g.image),
        plots: plots().map((canvas) => ({ canvas, length: plotLength(canvas) })),
        texts: copyTexts(),
        thumb: thumbnail(grabbed.map((g) => g.image)),
      });
      renderStrip();
      describe();
    },
    clear() {
      goLive({ restore: false });
      history.clear();
      steps = 0;
      strip.replaceChildren();
      describe();
    },
  };
}
