// Drawing wasm-rendered pixels: the source renders straight into the data of an ImageData that we
// keep per canvas and size, so a live view allocates nothing per frame.
const cache = new WeakMap();

/** Draws `source` (anything with width, height and renderInto(Uint8ClampedArray)) on `canvas`. */
export function drawInto(canvas, source) {
  const { width, height } = source;
  if (canvas.width !== width || canvas.height !== height) {
    canvas.width = width;
    canvas.height = height;
  }
  let image = cache.get(canvas);
  if (!image || image.width !== width || image.height !== height) {
    image = new ImageData(width, height);
    cache.set(canvas, image);
  }
  source.renderInto(image.data);
  canvas.getContext('2d').putImageData(image, 0, 0);
}

/** Draws an RGBA picture that `render(buffer)` writes over what `canvas` shows (alpha-blended). */
export function drawOverlay(canvas, width, height, render, alpha = 1) {
  const layer = document.createElement('canvas');
  layer.width = width;
  layer.height = height;
  const image = new ImageData(width, height);
  render(image.data);
  layer.getContext('2d').putImageData(image, 0, 0);
  const ctx = canvas.getContext('2d');
  ctx.save();
  ctx.globalAlpha = alpha;
  ctx.imageSmoothingEnabled = false;
  ctx.drawImage(layer, 0, 0, canvas.width, canvas.height);
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
