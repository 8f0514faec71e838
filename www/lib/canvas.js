// Drawing wasm-rendered pixels: the source renders straight into the data of an ImageData that we
// keep per canvas and size, so a live view allocates nothing per frame.
const cache = new WeakMap();

/**
 * Where `canvas`'s picture is on screen (client coordinates): its box, or with `object-fit:
 * contain` the part of the box the picture fills (a 4:3 map in a square box is letterboxed).
 */
export function shownRect(canvas) {
  const outer = canvas.getBoundingClientRect();
  if (getComputedStyle(canvas).objectFit !== 'contain' || !(canvas.width > 0 && canvas.height > 0)) return outer;
  const fit = Math.min(outer.width / canvas.width, outer.height / canvas.height);
  const [width, height] = [canvas.width * fit, canvas.height * fit];
  return { left: outer.left + (outer.width - width) / 2, top: outer.top + (outer.height - height) / 2, width, height };
}

/**
 * Draws `source` (anything with width, height and renderInto(Uint8ClampedArray)) on `canvas`. A
 * source that already holds its pixels as an ImageData (a worker session's mirror:
 * `imageData('renderInto')`) is put as it is, with no copy.
 */
export function drawInto(canvas, source) {
  const { width, height } = source;
  if (canvas.width !== width || canvas.height !== height) {
    canvas.width = width;
    canvas.height = height;
  }
  const direct = source.imageData?.('renderInto');
  if (direct) {
    canvas.getContext('2d').putImageData(direct, 0, 0);
    return;
  }
  let image = cache.get(canvas);
  if (!image || image.width !== width || image.height !== height) {
    image = new ImageData(width, height);
    cache.set(canvas, image);
  }
  source.renderInto(image.data);
  canvas.getContext('2d').putImageData(image, 0, 0);
}

// One scratch layer per canvas that overlays are drawn on: a live view at 1024x1024 would otherwise
// allocate a canvas and 4 MB of pixels per overlay per frame, and their collection shows up as
// main-thread pauses.
const layers = new WeakMap();

function layerFor(canvas, width, height) {
  let layer = layers.get(canvas);
  if (!layer || layer.canvas.width !== width || layer.canvas.height !== height) {
    const c = document.createElement('canvas');
    c.width = width;
    c.height = height;
    layer = { canvas: c, image: new ImageData(width, height) };
    layers.set(canvas, layer);
  }
  return layer;
}

/**
 * Draws an RGBA picture over what `canvas` shows (alpha-blended): `render(buffer)` writes it into a
 * cleared buffer, or `render` is an ImageData of `width` x `height` already.
 */
export function drawOverlay(canvas, width, height, render, alpha = 1) {
  const layer = layerFor(canvas, width, height);
  if (typeof render === 'function') {
    layer.image.data.fill(0);
    render(layer.image.data);
    layer.canvas.getContext('2d').putImageData(layer.image, 0, 0);
  } else {
    layer.canvas.getContext('2d').putImageData(render, 0, 0);
  }
  const ctx = canvas.getContext('2d');
  ctx.save();
  ctx.globalAlpha = alpha;
  ctx.imageSmoothingEnabled = false;
  ctx.drawImage(layer.canvas, 0, 0, canvas.width, canvas.height);
  ctx.restore();
}

/** Outlines a rectangle given in output pixels, wrapping around the borders if it runs past them. */
export function strokeRect(canvas, rect, outputWidth, outputHeight, color, dash = []) {
  const ctx = canvas.getContext('2d');
  const sx = canvas.width / outputWidth;
  const sy = canvas.height / outputHeight;
  ctx.save();
  ctx.strokeStyle = color;
  ctx.lineWidth = Math.max(1, sx);
  ctx.setLineDash(dash);
  for (const dx of [0, -outputWidth, outputWidth]) {
    for (const dy of [0, -outputHeight, outputHeight]) {
      ctx.strokeRect((rect.x + dx) * sx + 0.5, (rect.y + dy) * sy + 0.5, rect.width * sx - 1, rect.height * sy - 1);
    }
  }
  ctx.restore();
}
