// The large-upload prompt: an upload whose longer side is above the working size is not used at
// once. A camera photo (4000x3000) makes every method slower, and graph cut's search grows with
// the exemplar, so the page says so and lets the user shrink it, crop a square of it, or use it
// whole. The dialog (index.html, #large-upload) is modal: the run in progress goes on behind it,
// and Escape or Cancel keeps the previous exemplar.
import { drawInto } from './canvas.js';

// The crop view shows a shrunk copy of the photo; its longer side (the canvas's own pixels).
const PREVIEW_SIDE = 720;
// The smallest square the crop view allows, in image pixels.
const MIN_SIDE = 16;

const longer = (e) => Math.max(e.width, e.height);

/** The size `exemplar.resized(maxSide)` gives (the same rounding as the Rust side). */
function shrunkSize(width, height, maxSide) {
  const factor = Math.min(1, maxSide / Math.max(width, height));
  const side = (len) => Math.min(len, Math.max(1, Math.round(len * factor)));
  return [side(width), side(height)];
}

/**
 * Wires the prompt. `check(exemplar, label)` resolves to `{ exemplar, label }`, the exemplar to use
 * (the upload itself when it is within the working size), or to null when the user cancelled. The
 * prompt owns the upload from then on: it frees whatever it does not hand back.
 */
export function setupLargeUpload({ dialogEl, workingSizeEl }) {
  const q = (sel) => dialogEl.querySelector(sel);
  const el = {
    message: q('[data-part="message"]'),
    choices: q('[data-part="choices"]'),
    shrink: q('[data-choice="shrink"]'),
    crop: q('[data-choice="crop"]'),
    whole: q('[data-choice="whole"]'),
    cropView: q('[data-part="crop-view"]'),
    canvas: q('[data-part="crop-canvas"]'),
    readout: q('[data-part="crop-readout"]'),
    accept: q('[data-choice="accept"]'),
    back: q('[data-choice="back"]'),
  };
  const workingSize = () => Number(workingSizeEl.value) || 512;

  // The pending upload: its exemplar, label, the promise's resolve, and the crop state.
  let pending = null;
  // The photo's preview at the canvas's size (drawn under the square).
  const base = document.createElement('canvas');

  function settle(result) {
    const p = pending;
    if (!p) return;
    pending = null;
    // The preview's pixels are the next upload's to draw; none are kept meanwhile.
    base.width = base.height = 0;
    // Free the upload unless it is what we hand back.
    if (!result || result.exemplar !== p.exemplar) p.exemplar.free();
    if (dialogEl.open) dialogEl.close();
    p.resolve(result);
  }

  // Anything that goes wrong while making the chosen exemplar rejects the check (input.js shows it).
  function settleWith(make) {
    const p = pending;
    if (!p) return;
    try {
      settle(make(p));
    } catch (error) {
      pending = null;
      p.exemplar.free();
      if (dialogEl.open) dialogEl.close();
      p.reject(error);
    }
  }

  el.shrink.addEventListener('click', () =>
    settleWith((p) => ({ exemplar: p.exemplar.resized(p.size), label: `${p.label}, shrunk` })));
  el.whole.addEventListener('click', () => settleWith((p) => ({ exemplar: p.exemplar, label: p.label })));
  el.crop.addEventListener('click', showCrop);
  el.back.addEventListener('click', showChoices);
  el.accept.addEventListener('click', acceptCrop);
  for (const button of dialogEl.querySelectorAll('[data-choice="cancel"]')) {
    button.addEventListener('click', () => settle(null));
  }
  // Escape (the dialog's cancel) and any other close: the previous exemplar stays.
  // (The close event comes a task later: if another upload has opened the dialog since, it stays.)
  dialogEl.addEventListener('close', () => dialogEl.open || settle(null));

  function showChoices() {
    el.cropView.hidden = true;
    el.choices.hidden = false;
    el.crop.focus();
  }

  function showCrop() {
    const p = pending;
    const { width, height } = p.exemplar;
    if (!p.square) {
      const side = Math.min(p.size, width, height);
      p.square = { x: Math.floor((width - side) / 2), y: Math.floor((height - side) / 2), side };
    }
    if (!p.previewDrawn) {
      // Shrunk in wasm (area averaging) rather than the full photo drawn and scaled by the canvas:
      // a 4000x3000 photo would need a 48 MB ImageData.
      const preview = p.exemplar.resized(Math.min(PREVIEW_SIDE, longer(p.exemplar)));
      try {
        drawInto(base, preview);
      } finally {
        preview.free();
      }
      el.canvas.width = base.width;
      el.canvas.height = base.height;
      p.previewDrawn = true;
    }
    el.choices.hidden = true;
    el.cropView.hidden = false;
    drawSquare();
    el.canvas.focus();
  }

  /** A side between MIN_SIDE and the photo's shorter side, in whole pixels. */
  function clampSide(side) {
    const shorter = Math.min(pending.exemplar.width, pending.exemplar.height);
    return Math.round(Math.min(shorter, Math.max(Math.min(MIN_SIDE, shorter), side)));
  }

  /** Keeps the square inside the photo, its side within clampSide. */
  function clampSquare(s) {
    const { width, height } = pending.exemplar;
    const side = clampSide(s.side);
    return {
      side,
      x: Math.round(Math.min(width - side, Math.max(0, s.x))),
      y: Math.round(Math.min(height - side, Math.max(0, s.y))),
    };
  }

  function setSquare(s) {
    pending.square = clampSquare(s);
    drawSquare();
  }

  function drawSquare() {
    const p = pending;
    const { x, y, side } = p.square;
    const ctx = el.canvas.getContext('2d');
    const k = el.canvas.width / p.exemplar.width;
    const [sx, sy, ss] = [x * k, y * k, side * k];
    ctx.drawImage(base, 0, 0);
    // Dim what the crop leaves out, so the square reads at a glance on any photo.
    ctx.fillStyle = 'rgba(0, 0, 0, 0.55)';
    ctx.beginPath();
    ctx.rect(0, 0, el.canvas.width, el.canvas.height);
    ctx.rect(sx, sy, ss, ss);
    ctx.fill('evenodd');
    ctx.lineWidth = 2;
    ctx.strokeStyle = '#e0a458';
    ctx.strokeRect(sx + 1, sy + 1, ss - 2, ss - 2);
    const { width, height } = p.exemplar;
    const result = side > p.size ? `, shrunk to ${p.size}×${p.size} on use` : '';
    el.readout.textContent = `Square ${side}×${side} px at (${x}, ${y}) of ${width}×${height}${result}`;
    dialogEl.dataset.crop = `${x},${y},${side}`;
  }

  function acceptCrop() {
    settleWith((p) => {
      const { x, y, side } = p.square;
      const label = `${p.label}, crop ${side}×${side} at (${x}, ${y})`;
      const crop = p.exemplar.cropped(x, y, side, side);
      if (side <= p.size) return { exemplar: crop, label };
      try {
        return { exemplar: crop.resized(p.size), label };
      } finally {
        crop.free();
      }
    });
  }

  // Keyboard: arrows move the square (Shift: ten times further), + and - resize it around its
  // centre, Enter uses it. Steps are a share of the photo, so a 4000-pixel photo is not 4000 presses.
  el.canvas.addEventListener('keydown', (event) => {
    if (!pending?.square) return;
    const { width, height } = pending.exemplar;
    const s = pending.square;
    const move = Math.max(1, Math.round(Math.max(width, height) / 100)) * (event.shiftKey ? 10 : 1);
    const grow = Math.max(8, Math.round(Math.min(width, height) / 256) * 8);
    const resize = (d) => {
      const side = clampSide(s.side + d);
      const shift = Math.round((side - s.side) / 2);
      return { x: s.x - shift, y: s.y - shift, side };
    };
    const next = {
      ArrowLeft: { ...s, x: s.x - move },
      ArrowRight: { ...s, x: s.x + move },
      ArrowUp: { ...s, y: s.y - move },
      ArrowDown: { ...s, y: s.y + move },
      '+': resize(grow),
      '=': resize(grow),
      '-': resize(-grow),
      _: resize(-grow),
    }[event.key];
    if (next) {
      event.preventDefault();
      setSquare(next);
    } else if (event.key === 'Enter') {
      event.preventDefault();
      acceptCrop();
    }
  });

  // Pointer: a drag that starts inside the square moves it; one that starts outside draws a new
  // square from that corner (a click outside centres the square there).
  let drag = null;
  const toImage = (event) => {
    const rect = el.canvas.getBoundingClientRect();
    return {
      x: ((event.clientX - rect.left) / rect.width) * pending.exemplar.width,
      y: ((event.clientY - rect.top) / rect.height) * pending.exemplar.height,
    };
  };
  el.canvas.addEventListener('pointerdown', (event) => {
    if (!pending?.square || event.button !== 0) return;
    event.preventDefault();
    el.canvas.focus();
    el.canvas.setPointerCapture(event.pointerId);
    const at = toImage(event);
    const s = pending.square;
    const inside = at.x >= s.x && at.x < s.x + s.side && at.y >= s.y && at.y < s.y + s.side;
    drag = inside ? { mode: 'move', dx: at.x - s.x, dy: at.y - s.y } : { mode: 'draw', from: at, moved: false };
  });
  el.canvas.addEventListener('pointermove', (event) => {
    if (!drag || !pending) return;
    const at = toImage(event);
    if (drag.mode === 'move') {
      setSquare({ ...pending.square, x: at.x - drag.dx, y: at.y - drag.dy });
      return;
    }
    const dx = at.x - drag.from.x;
    const dy = at.y - drag.from.y;
    const side = Math.max(Math.abs(dx), Math.abs(dy));
    if (side < MIN_SIDE && !drag.moved) return;
    drag.moved = true;
    // Clamp the side first, so a square drawn towards the top or left keeps its far corner put.
    const { width, height } = pending.exemplar;
    const room = Math.min(
      dx < 0 ? drag.from.x : width - drag.from.x,
      dy < 0 ? drag.from.y : height - drag.from.y,
    );
    const fit = Math.max(MIN_SIDE, Math.min(side, room));
    setSquare({ side: fit, x: dx < 0 ? drag.from.x - fit : drag.from.x, y: dy < 0 ? drag.from.y - fit : drag.from.y });
  });
  const endDrag = (event) => {
    if (!drag || !pending) return;
    if (drag.mode === 'draw' && !drag.moved && event.type === 'pointerup') {
      const s = pending.square;
      setSquare({ ...s, x: drag.from.x - s.side / 2, y: drag.from.y - s.side / 2 });
    }
    drag = null;
  };
  el.canvas.addEventListener('pointerup', endDrag);
  el.canvas.addEventListener('pointercancel', endDrag);

  /** Resolves to the exemplar to use (see setupLargeUpload); opens the dialog only when needed. */
  function check(exemplar, label) {
    const size = workingSize();
    if (longer(exemplar) <= size) return Promise.resolve({ exemplar, label });
    // A second upload while one is pending (a drop is still possible): the first is dropped.
    settle(null);
    return new Promise((resolve, reject) => {
      pending = { exemplar, label, size, resolve, reject, square: null, previewDrawn: false };
      const { width, height } = exemplar;
      const [sw, sh] = shrunkSize(width, height, size);
      el.message.textContent =
        `${label} is ${width}×${height}; the working size is ${size}. Large exemplars make every ` +
        'method slower (graph cut\u2019s search grows with the exemplar).';
      el.shrink.textContent = `Shrink to ${size} (${sw}×${sh})`;
      el.whole.textContent = `Use it whole (${width}×${height})`;
      dialogEl.dataset.size = `${width}x${height}`;
      delete dialogEl.dataset.crop;
      el.cropView.hidden = true;
      el.choices.hidden = false;
      dialogEl.showModal();
      el.shrink.focus();
    });
  }

  return { check, workingSize };
}
