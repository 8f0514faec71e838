// Guide images for guided synthesis, made in JS: luminance, a picture resized to the output by
// drawing it into a canvas of that size, built-in gradients, and the luminance remapping of
// Hertzmann et al.'s image analogies (the target's luminance shifted and scaled to the mean and
// spread of the exemplar's, so that the guide asks for values the exemplar has). Luminance
// values are 0-255 in a Float32Array, one per pixel; `greyRgba` turns them into the grey RGBA
// that `Exemplar.fromRgba` compacts to one channel.

/** The luminance of every pixel of RGBA `data` (the weights of the package's own grey). */
export function luminance(data) {
  const out = new Float32Array(data.length / 4);
  for (let i = 0; i < out.length; i++) {
    out[i] = 0.299 * data[i * 4] + 0.587 * data[i * 4 + 1] + 0.114 * data[i * 4 + 2];
  }
  return out;
}

/** Opaque grey RGBA with `values` in red, green and blue. */
export function greyRgba(values) {
  const rgba = new Uint8ClampedArray(values.length * 4);
  for (let i = 0; i < values.length; i++) {
    rgba[i * 4] = rgba[i * 4 + 1] = rgba[i * 4 + 2] = values[i];
    rgba[i * 4 + 3] = 255;
  }
  return rgba;
}

function meanAndSpread(values) {
  let sum = 0;
  for (const v of values) sum += v;
  const mean = sum / values.length;
  let squares = 0;
  for (const v of values) squares += (v - mean) ** 2;
  return { mean, spread: Math.sqrt(squares / values.length) };
}

/** `target` shifted and scaled to the mean and standard deviation of `reference` (a flat
 * target stays flat, at the reference's mean). */
export function remapLuminance(target, reference) {
  const t = meanAndSpread(target);
  const r = meanAndSpread(reference);
  const scale = t.spread > 1e-6 ? r.spread / t.spread : 0;
  return target.map((v) => Math.min(255, Math.max(0, r.mean + (v - t.mean) * scale)));
}

/** `values` (a `width` x `height` image) blurred by a Gaussian of standard deviation `sigma`
 * pixels, separably, with the edge pixels repeated. */
export function blurred(values, width, height, sigma) {
  const radius = Math.ceil(3 * sigma);
  const kernel = Array.from({ length: 2 * radius + 1 }, (_, i) => Math.exp(-((i - radius) ** 2) / (2 * sigma * sigma)));
  const total = kernel.reduce((a, b) => a + b, 0);
  const pass = (input, along) => {
    const out = new Float32Array(input.length);
    const [n, lines] = along === 'x' ? [width, height] : [height, width];
    for (let line = 0; line < lines; line++) {
      for (let i = 0; i < n; i++) {
        let sum = 0;
        for (let k = -radius; k <= radius; k++) {
          const j = Math.min(n - 1, Math.max(0, i + k));
          sum += kernel[k + radius] * input[along === 'x' ? line * width + j : j * width + line];
        }
        out[along === 'x' ? line * width + i : i * width + line] = sum / total;
      }
    }
    return out;
  };
  return pass(pass(values, 'x'), 'y');
}

/** A built-in target: 'gradient' dark on the left to bright on the right, 'radial' bright in the
 * centre to dark at the corners. */
export function gradientLuminance(width, height, kind) {
  const out = new Float32Array(width * height);
  const [cx, cy] = [(width - 1) / 2, (height - 1) / 2];
  const reach = Math.hypot(cx, cy) || 1;
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const t = kind === 'radial' ? 1 - Math.hypot(x - cx, y - cy) / reach : x / Math.max(1, width - 1);
      out[y * width + x] = 255 * t;
    }
  }
  return out;
}

/** The RGBA pixels of a `source` picture (RGBA `data` of `sourceWidth` x `sourceHeight`)
 * stretched to `width` x `height` by the canvas's smoothed drawing. */
export function resizedRgba(data, sourceWidth, sourceHeight, width, height) {
  const source = document.createElement('canvas');
  source.width = sourceWidth;
  source.height = sourceHeight;
  source.getContext('2d').putImageData(new ImageData(new Uint8ClampedArray(data), sourceWidth, sourceHeight), 0, 0);
  const target = document.createElement('canvas');
  target.width = width;
  target.height = height;
  const ctx = target.getContext('2d', { willReadFrequently: true });
  ctx.imageSmoothingEnabled = true;
  ctx.imageSmoothingQuality = 'high';
  ctx.drawImage(source, 0, 0, width, height);
  return ctx.getImageData(0, 0, width, height).data;
}
