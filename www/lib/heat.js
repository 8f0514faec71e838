// A heat ramp and a grid painter for the teaching views (cost surfaces, seam graphs, IRLS
// weights): one value per cell, scaled up without smoothing so every cell stays visible.

/** Dark blue through purple and orange to pale yellow, for t in 0..1 (clamped). */
export function heat(t) {
  const stops = [[12, 14, 40], [80, 30, 110], [190, 60, 80], [245, 150, 50], [250, 240, 170]];
  const x = Math.min(1, Math.max(0, t)) * (stops.length - 1);
  const i = Math.min(stops.length - 2, Math.floor(x));
  const f = x - i;
  return stops[i].map((a, c) => Math.round(a + (stops[i + 1][c] - a) * f));
}

/** Paints `colour(k)` (an [r, g, b]) for each cell of a `width` x `height` grid over all of
 * `canvas`; returns the canvas's context for drawing on top. */
export function paintGrid(canvas, width, height, colour) {
  const image = new ImageData(width, height);
  for (let k = 0; k < width * height; k++) image.data.set([...colour(k), 255], 4 * k);
  const layer = document.createElement('canvas');
  layer.width = width;
  layer.height = height;
  layer.getContext('2d').putImageData(image, 0, 0);
  const ctx = canvas.getContext('2d');
  ctx.imageSmoothingEnabled = false;
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  ctx.drawImage(layer, 0, 0, canvas.width, canvas.height);
  return ctx;
}
