// The hole of the "Fill and extend" panel: a mask over the image (one byte per pixel, non-zero:
// fill it), the round brush that paints or erases it along the pointer's path, and the drawing
// of what is still to fill over a picture (tinted), with plain outlines for a patch or a region.
import { drawOverlay } from '../lib/canvas.js';

/** What is still to fill, drawn over the picture. */
export const HOLE_TINT = [255, 64, 170, 165];

/** An empty hole over a `width` x `height` image; `pixels` counts the marked ones. */
export function createHole(width, height) {
  return { width, height, mask: new Uint8Array(width * height), pixels: 0 };
}

/** Marks (`value` 1) or clears (0) the pixels within `radius` of (`x`, `y`), in image pixels. */
export function paintDab(hole, x, y, radius, value) {
  const { width, height, mask } = hole;
  const r = Math.max(0.5, radius);
  const [x0, x1] = [Math.max(0, Math.floor(x - r)), Math.min(width - 1, Math.ceil(x + r))];
  const [y0, y1] = [Math.max(0, Math.floor(y - r)), Math.min(height - 1, Math.ceil(y + r))];
  for (let py = y0; py <= y1; py++) {
    for (let px = x0; px <= x1; px++) {
      const [dx, dy] = [px + 0.5 - x, py + 0.5 - y];
      if (dx * dx + dy * dy > r * r) continue;
      const i = py * width + px;
      if (mask[i] !== value) hole.pixels += value ? 1 : -1;
      mask[i] = value;
    }
  }
}

/**
 * Paints from `from` to `to` ({ x, y } in image pixels; `from` null: a single dab), with dabs
 * close enough together that a fast pointer leaves no gaps.
 */
export function paintStroke(hole, from, to, radius, value) {
  const start = from ?? to;
  const length = Math.hypot(to.x - start.x, to.y - start.y);
  const dabs = Math.max(1, Math.ceil(length / Math.max(0.5, radius / 2)));
  for (let k = 1; k <= dabs; k++) {
    const t = from ? k / dabs : 1;
    paintDab(hole, start.x + (to.x - start.x) * t, start.y + (to.y - start.y) * t, radius, value);
  }
}

/** Where a pointer event falls on `canvas`, in the pixels of a `width` x `height` image. */
export function pointerPixel(canvas, event, width, height) {
  const box = canvas.getBoundingClientRect();
  return {
    x: ((event.clientX - box.left) / box.width) * width,
    y: ((event.clientY - box.top) / box.height) * height,
  };
}

/**
 * Tints the pixels of `mask` still to fill over what `canvas` shows. `patches`, the fill's
 * patches view (an ImageData: unfilled pixels are transparent), leaves the filled ones out.
 */
export function drawHole(canvas, width, height, mask, patches = null) {
  drawOverlay(canvas, width, height, (buffer) => {
    const alpha = patches?.data;
    for (let i = 0; i < mask.length; i++) {
      if (mask[i] && (!alpha || alpha[i * 4 + 3] === 0)) buffer.set(HOLE_TINT, i * 4);
    }
  });
}

/** Outlines `rect` ({ x, y, width, height } in image pixels) on `canvas`, clipped, not wrapped. */
export function outline(canvas, rect, width, height, colour, dash = []) {
  const ctx = canvas.getContext('2d');
  const [sx, sy] = [canvas.width / width, canvas.height / height];
  ctx.save();
  ctx.strokeStyle = colour;
  ctx.lineWidth = Math.max(1, sx / 2);
  ctx.setLineDash(dash);
  ctx.strokeRect(rect.x * sx + 0.5, rect.y * sy + 0.5, rect.width * sx - 1, rect.height * sy - 1);
  ctx.restore();
}
