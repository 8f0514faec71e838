#!/usr/bin/env node
// Makes the demo clips of graph-cut video textures, written as PNG film strips (frames stacked
// top to bottom) into www/samples/clips/. Deterministic: the same file every run, so the
// repository can always rebuild them and the tests can rely on them.
//
//   node scripts/make-demo-clip.mjs [--clip water|ripples] [--size 128] [--frames 60] [--out FILE]
//
// water: a sum of travelling waves whose angular speeds are not multiples of 2 pi / frames, so the
// clip itself does not loop: making it loop is the synthesis's job. Its waves cover the whole
// frame alike, so a loop's best cut in time is nearly the same at every pixel.
//
// ripples: a pond with three sources of circular ripples, each with its own frequency and a slow
// swell of its own period and phase, so that the motion differs across the frame: where one
// source's swell matches itself a loop length later, another's does not. A loop's seam surface
// (7.A) then cuts at a different time in different parts of the frame.
//
// Colour comes from the height (deep to shallow) and from the slope (bright caustic-like ridges).
import { writeFileSync, mkdirSync } from 'node:fs';
import { dirname } from 'node:path';
import { deflateSync } from 'node:zlib';

const args = Object.fromEntries(
  process.argv.slice(2).reduce((pairs, arg, i, all) => (arg.startsWith('--') ? [...pairs, [arg.slice(2), all[i + 1]]] : pairs), []),
);
const clip = args.clip ?? 'water';
const size = Number(args.size ?? 128);
const frames = Number(args.frames ?? 60);
const out = args.out ?? new URL(`../www/samples/clips/${clip}.png`, import.meta.url).pathname;

// A small deterministic generator (mulberry32) for the wave parameters.
let state = 0x2f6b1d3;
const random = () => {
  state = (state + 0x6d2b79f5) | 0;
  let t = Math.imul(state ^ (state >>> 15), 1 | state);
  t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
  return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
};

/** The water surface: travelling plane waves over the whole frame. */
function waterHeight() {
  const waves = Array.from({ length: 9 }, (_, k) => {
    const angle = random() * 2 * Math.PI;
    const wavelength = 10 + random() * 38;
    const number = (2 * Math.PI) / wavelength;
    return {
      kx: Math.cos(angle) * number,
      ky: Math.sin(angle) * number,
      // Deep-water dispersion (omega ~ sqrt(k)), scaled so a wave moves a few pixels per frame.
      omega: 0.55 * Math.sqrt(number * 9.81) * (0.8 + 0.4 * random()),
      phase: random() * 2 * Math.PI,
      amplitude: (wavelength / 48) * (0.6 + 0.4 * random()) / (1 + k * 0.15),
    };
  });
  return (x, y, t) => waves.reduce((h, w) => h + w.amplitude * Math.sin(w.kx * x + w.ky * y - w.omega * t + w.phase), 0);
}

/**
 * The pond: three ripple sources at fixed places (in fractions of the frame), each with its own
 * wavelength and speed, its amplitude fading with distance and swelling and ebbing over a period
 * of its own; a faint, slow background swell everywhere.
 */
function ripplesHeight() {
  const sources = [
    { x: 0.18, y: 0.25, wavelength: 11, speed: 1.3, swell: 37, phase: 0.3 },
    { x: 0.8, y: 0.35, wavelength: 17, speed: 1.9, swell: 53, phase: 2.4 },
    { x: 0.45, y: 0.85, wavelength: 8, speed: 0.9, swell: 29, phase: 4.4 },
  ].map((s) => ({ ...s, x: s.x * size, y: s.y * size, reach: 0.3 * size, start: random() * 2 * Math.PI }));
  return (x, y, t) => sources.reduce((h, s) => {
    const r = Math.hypot(x - s.x, y - s.y);
    const k = (2 * Math.PI) / s.wavelength;
    const swell = 0.5 + 0.5 * Math.sin((2 * Math.PI * t) / s.swell + s.phase);
    const fade = Math.exp(-r / s.reach) / Math.sqrt(1 + r / s.wavelength);
    return h + 1.6 * swell * fade * Math.sin(k * (r - s.speed * t) + s.start);
  }, 0.15 * Math.sin(0.05 * x + 0.03 * y - 0.07 * t));
}

const [height, palette] = {
  water: [waterHeight, { base: [10, 60, 110], level: [60, 110, 110], glint: [190, 150, 90] }],
  ripples: [ripplesHeight, { base: [20, 55, 45], level: [50, 120, 90], glint: [200, 190, 120] }],
}[clip]?.map((v, i) => (i === 0 ? v() : v)) ?? (() => {
  console.error(`make-demo-clip: --clip must be water or ripples, got ${clip}`);
  process.exit(2);
})();

const rgb = new Uint8Array(size * size * frames * 3);
for (let t = 0; t < frames; t++) {
  for (let y = 0; y < size; y++) {
    for (let x = 0; x < size; x++) {
      const h = height(x, y, t);
      const slope = Math.hypot(height(x + 1, y, t) - height(x - 1, y, t), height(x, y + 1, t) - height(x, y - 1, t));
      const level = Math.min(1, Math.max(0, 0.5 + h * 0.35));
      const glint = Math.min(1, Math.max(0, (0.09 - slope) * 9)) ** 3;
      const i = ((t * size + y) * size + x) * 3;
      for (let c = 0; c < 3; c++) {
        rgb[i + c] = Math.round(Math.min(255, palette.base[c] + palette.level[c] * level + palette.glint[c] * glint));
      }
    }
  }
}

// A minimal PNG writer: 8-bit RGB, filter "up" on every row (smooth frames compress well with it).
const crcTable = Array.from({ length: 256 }, (_, n) => {
  let c = n;
  for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
  return c >>> 0;
});
const crc32 = (bytes) => {
  let c = 0xffffffff;
  for (const b of bytes) c = crcTable[(c ^ b) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
};
const chunk = (type, data) => {
  const body = Buffer.concat([Buffer.from(type, 'ascii'), data]);
  const length = Buffer.alloc(4);
  length.writeUInt32BE(data.length);
  const crc = Buffer.alloc(4);
  crc.writeUInt32BE(crc32(body));
  return Buffer.concat([length, body, crc]);
};
const stripHeight = size * frames;
const stride = size * 3;
const raw = Buffer.alloc(stripHeight * (stride + 1));
for (let y = 0; y < stripHeight; y++) {
  raw[y * (stride + 1)] = 2; // up
  for (let i = 0; i < stride; i++) {
    const above = y > 0 ? rgb[(y - 1) * stride + i] : 0;
    raw[y * (stride + 1) + 1 + i] = (rgb[y * stride + i] - above) & 0xff;
  }
}
const header = Buffer.alloc(13);
header.writeUInt32BE(size, 0);
header.writeUInt32BE(stripHeight, 4);
header.set([8, 2, 0, 0, 0], 8);
const png = Buffer.concat([
  Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]),
  chunk('IHDR', header),
  chunk('IDAT', deflateSync(raw, { level: 9 })),
  chunk('IEND', Buffer.alloc(0)),
]);
mkdirSync(dirname(out), { recursive: true });
writeFileSync(out, png);
console.log(`make-demo-clip: ${out}: ${size}x${size}, ${frames} frames, ${png.length} bytes`);
