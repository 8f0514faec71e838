// Shared inputs of the Node tests against the built package (pkg/, made by ./scripts/build.sh):
// the package itself, loaded the way a Node user loads it, and tiny exemplars so that hundreds
// of sessions run in seconds.
import { existsSync, readFileSync } from 'node:fs';

/**
 * The build under test: the single-threaded module, or with TEXSYNTH_TEST_BUILD=threads the
 * threaded one (pkg/threads.js, on its default pool), which must take the same calls.
 */
export const build = process.env.TEXSYNTH_TEST_BUILD === 'threads' ? 'threads' : 'single';
export const api = await import(build === 'threads' ? '../../pkg/threads.js' : '../../pkg/node.js');

/** Whether the package holds the threaded module (the build had its nightly). */
export const threadedBuilt = existsSync(new URL('../../pkg/threads/texsynth_bg.wasm', import.meta.url));

/** The bytes of a sample texture of www/samples. */
export const sampleBytes = (name = 'gravel_64') =>
  new Uint8Array(readFileSync(new URL(`../../www/samples/${name}.png`, import.meta.url)));

/** A `side` x `side` exemplar shrunk from a sample (a fresh object each call: tests free it). */
export function tinyExemplar(side = 32, name = 'gravel_64') {
  const full = api.Exemplar.fromBytes(sampleBytes(name));
  const small = full.resized(side);
  full.free();
  return small;
}

/** A `side` x `side` x `frames` clip of moving stripes, RGBA frames one after another. */
export function tinyClip(side = 12, frames = 8) {
  const rgba = new Uint8Array(side * side * 4 * frames);
  for (let t = 0; t < frames; t++) {
    for (let y = 0; y < side; y++) {
      for (let x = 0; x < side; x++) {
        const i = ((t * side + y) * side + x) * 4;
        const v = 128 + 100 * Math.sin(0.7 * x + 0.3 * y - 0.5 * t);
        rgba.set([v, 255 - v, (x * 20) & 255, 255], i);
      }
    }
  }
  return api.VideoClip.fromFrames(side, side, frames, rgba);
}

/** The RGBA output of a session of any kind, in a buffer of the type its renderInto takes. */
export function render(session) {
  const buffer = session instanceof api.VideoTextures
    ? new Uint8Array(session.width * session.height * 4)
    : new Uint8ClampedArray(session.width * session.height * 4);
  session.renderInto(buffer);
  return buffer;
}
