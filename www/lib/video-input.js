// Video input for the page: a clip is { width, height, frames, rgba } with the frames' RGBA
// bytes one after the other. Three ways in, all downscaled to a chosen size in a canvas:
// - a video file, decoded frame by frame through a <video> element (seek, wait for the frame,
//   draw); the browser's decoder, so every format it plays works;
// - an image sequence (several files, taken in name order);
// - a film strip: one image with the frames stacked top to bottom (the demo clip).

/** Draws `source` (sw x sh) scaled to cover `width` x `height`, centred, and returns its RGBA. */
function grab(ctx, source, sw, sh, width, height) {
  const scale = Math.max(width / sw, height / sh);
  const [dw, dh] = [sw * scale, sh * scale];
  ctx.clearRect(0, 0, width, height);
  ctx.drawImage(source, (width - dw) / 2, (height - dh) / 2, dw, dh);
  return ctx.getImageData(0, 0, width, height).data;
}

function scratchContext(width, height) {
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  return canvas.getContext('2d', { willReadFrequently: true });
}

function clipOf(width, height, frames) {
  const rgba = new Uint8Array(width * height * 4 * frames.length);
  frames.forEach((frame, t) => rgba.set(frame, t * width * height * 4));
  return { width, height, frames: frames.length, rgba };
}

/** The frames of a film strip image (`frameHeight` tall each; default: square frames). */
export function clipFromStrip(image, { width, height, frameHeight } = {}) {
  const stripFrame = frameHeight ?? image.naturalWidth;
  const count = Math.floor(image.naturalHeight / stripFrame);
  if (count < 2) throw new Error(`a film strip needs at least 2 frames; this image has ${count}`);
  const [w, h] = [width ?? image.naturalWidth, height ?? stripFrame];
  const ctx = scratchContext(w, h);
  const frames = [];
  for (let t = 0; t < count; t++) {
    ctx.clearRect(0, 0, w, h);
    ctx.drawImage(image, 0, t * stripFrame, image.naturalWidth, stripFrame, 0, 0, w, h);
    frames.push(ctx.getImageData(0, 0, w, h).data);
  }
  return clipOf(w, h, frames);
}

/** Loads an image from a URL or a File. */
export function loadImage(source) {
  return new Promise((resolve, reject) => {
    const image = new Image();
    const url = typeof source === 'string' ? source : URL.createObjectURL(source);
    image.onload = () => resolve(image);
    image.onerror = () => reject(new Error(`could not decode ${source.name ?? source} as an image`));
    image.src = url;
  });
}

/** An image sequence: the files in name order, each scaled to `width` x `height`. */
export async function clipFromImages(files, { width, height }) {
  const sorted = [...files].sort((a, b) => a.name.localeCompare(b.name, undefined, { numeric: true }));
  if (sorted.length < 2) throw new Error(`an image sequence needs at least 2 images, got ${sorted.length}`);
  const ctx = scratchContext(width, height);
  const frames = [];
  for (const file of sorted) {
    const image = await loadImage(file);
    frames.push(grab(ctx, image, image.naturalWidth, image.naturalHeight, width, height));
  }
  return clipOf(width, height, frames);
}

/**
 * A video file decoded through a <video> element: `frames` frames taken `fps` per second from
 * the start (or fewer if the video is shorter), each scaled to `width` x `height`.
 */
export async function clipFromVideo(file, { width, height, frames, fps = 15, onProgress }) {
  const video = document.createElement('video');
  video.muted = true;
  video.playsInline = true;
  video.preload = 'auto';
  const url = URL.createObjectURL(file);
  video.src = url;
  try {
    await new Promise((resolve, reject) => {
      video.onloadeddata = resolve;
      video.onerror = () => reject(new Error(`this browser cannot decode ${file.name ?? 'the video'}`));
    });
    const seek = (time) => new Promise((resolve, reject) => {
      video.onseeked = resolve;
      video.onerror = () => reject(new Error(`decoding failed at ${time.toFixed(2)} s`));
      video.currentTime = time;
    });
    // A recorded WebM (MediaRecorder's, for one) may not state its duration: seeking far past
    // the end makes the browser read to the end and learn it.
    if (!Number.isFinite(video.duration)) await seek(1e6);
    const count = Math.min(frames, Math.max(2, Math.floor(video.duration * fps)));
    const ctx = scratchContext(width, height);
    const out = [];
    for (let t = 0; t < count; t++) {
      await seek(Math.min(video.duration, t / fps));
      out.push(grab(ctx, video, video.videoWidth, video.videoHeight, width, height));
      onProgress?.(t + 1, count);
    }
    return clipOf(width, height, out);
  } finally {
    URL.revokeObjectURL(url);
  }
}
