// Keyboard painting: every canvas the page paints on with the pointer can be
// painted with the keyboard too. Such a canvas is made `paintable`: it takes focus, the arrows move
// a brush cursor over it (Shift: five times further), Space held paints along the path the arrows
// take (Space down starts the stroke, the arrows draw it, Space up ends it), and Enter paints one
// dab (and clicks there, for canvases that act on a click). The panels' own pointer handlers do
// the painting: they receive pointer events at the cursor, so a keyboard stroke is the same
// stroke a pointer would make.

import { shownRect } from './canvas.js';

const HELP = 'arrows move the brush (Shift: faster), hold Space to paint, Enter paints one dab';
/**
 * canvas -> { fx, fy, down }: the cursor as a share of the picture shown (a letterboxed canvas's
 * bars are not part of it), and whether a stroke is on.
 */
const cursors = new WeakMap();
let ring = null;

/** Makes `canvas` paintable with the keyboard; `name` says what painting it does. */
export function paintable(canvas, name) {
  canvas.tabIndex = 0;
  canvas.dataset.paint = name;
  canvas.setAttribute('aria-description', `${name}: ${HELP}`);
}

/** Undoes `paintable` (a shared canvas that another panel paints differently or not at all). */
export function unpaintable(canvas) {
  end(canvas);
  canvas.removeAttribute('tabindex');
  delete canvas.dataset.paint;
  canvas.removeAttribute('aria-description');
  hideRing();
}

/** Listens for the brush keys on every paintable canvas below `root`. */
export function installKeyboardBrush(root = document) {
  root.addEventListener('keydown', (event) => {
    const canvas = event.target;
    if (!(canvas instanceof HTMLCanvasElement) || canvas.dataset.paint === undefined) return;
    const cursor = cursorOf(canvas);
    const step = (event.shiftKey ? 5 : 1) / 50;
    const moves = { ArrowLeft: [-step, 0], ArrowRight: [step, 0], ArrowUp: [0, -step], ArrowDown: [0, step] };
    if (moves[event.key]) {
      event.preventDefault();
      const [dx, dy] = moves[event.key];
      cursor.fx = Math.min(1, Math.max(0, cursor.fx + dx));
      cursor.fy = Math.min(1, Math.max(0, cursor.fy + dy));
      send(canvas, 'pointermove');
      showRing(canvas);
    } else if (event.key === ' ') {
      event.preventDefault();
      if (!cursor.down) {
        cursor.down = true;
        send(canvas, 'pointerdown');
      }
      showRing(canvas);
    } else if (event.key === 'Enter') {
      event.preventDefault();
      send(canvas, 'pointerdown');
      end(canvas, true);
      send(canvas, 'click');
      showRing(canvas);
    }
  });
  root.addEventListener('keyup', (event) => {
    if (event.key === ' ' && event.target instanceof HTMLCanvasElement) end(event.target);
  });
  root.addEventListener('focusin', (event) => {
    if (event.target instanceof HTMLCanvasElement && event.target.dataset.paint !== undefined) showRing(event.target);
  });
  root.addEventListener('focusout', (event) => {
    if (event.target instanceof HTMLCanvasElement) {
      end(event.target);
      hideRing();
    }
  });
}

function cursorOf(canvas) {
  if (!cursors.has(canvas)) cursors.set(canvas, { fx: 0.5, fy: 0.5, down: false });
  return cursors.get(canvas);
}

/** Ends a stroke under way (or, with `always`, the one-dab stroke Enter started). */
function end(canvas, always = false) {
  const cursor = cursors.get(canvas);
  if (!cursor || (!cursor.down && !always)) return;
  cursor.down = false;
  ring?.classList.remove('painting');
  send(canvas, 'pointerup');
}

/** A pointer event at the cursor; it bubbles, so the panels' window `pointerup` sees it too. */
function send(canvas, type) {
  const { fx, fy } = cursorOf(canvas);
  const rect = shownRect(canvas);
  const at = { clientX: rect.left + fx * rect.width, clientY: rect.top + fy * rect.height };
  const init = { ...at, bubbles: true, button: 0, buttons: type === 'pointerdown' || type === 'pointermove' ? 1 : 0 };
  canvas.dispatchEvent(type === 'click' ? new MouseEvent(type, init) : new PointerEvent(type, { ...init, isPrimary: true }));
}

/** The brush cursor: a ring over the canvas (an element of its own, so no canvas pixel changes). */
function showRing(canvas) {
  if (!ring) {
    ring = document.createElement('div');
    ring.className = 'brush-ring';
    ring.setAttribute('aria-hidden', 'true');
    document.body.append(ring);
  }
  const { fx, fy, down } = cursorOf(canvas);
  const rect = shownRect(canvas);
  ring.style.left = `${rect.left + fx * rect.width}px`;
  ring.style.top = `${rect.top + fy * rect.height}px`;
  ring.classList.toggle('painting', down);
  ring.hidden = false;
  canvas.dataset.brush = `${fx.toFixed(2)},${fy.toFixed(2)}`;
}

function hideRing() {
  if (ring) ring.hidden = true;
}
