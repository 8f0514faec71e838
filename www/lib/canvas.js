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
