// The sources of the "Graph-cut merge" panel: up to 8 images, the exemplar first, each with its
// top-left corner at an (x, y) position. Here: their rows in the panel's options, the list as one
// field of the page's URL state, the output box around them, which pixels the brush may paint
// for each source (the rule GraphcutMerge's first step checks), and how many pixels of the
// result each source gave.
import { SAMPLES } from '../lib/samples.js';

/** GraphcutMerge takes at most this many sources. */
export const MAX_SOURCES = 8;

/** Each source's colour (its paint, its outline, its swatch), by source index; red is the seams'. */
export const COLOURS = [
  [80, 170, 255], [255, 120, 60], [90, 220, 110], [230, 90, 220],
  [250, 220, 60], [60, 225, 225], [165, 125, 255], [235, 235, 235],
];

/** The paint's opacity over the picture (of 255). */
const PAINT_ALPHA = 150;

/** What the row of each source index starts with: the exemplar at the origin, then samples
 * placed to overlap what is above and beside them. */
const DEFAULTS = [
  { sample: null, x: 0, y: 0 },
  { sample: 'sand_128', x: 64, y: 0 },
  { sample: 'brick_128', x: 32, y: 64 },
  { sample: 'grass_128', x: 96, y: 64 },
  { sample: 'stone_128', x: 0, y: 128 },
  { sample: 'planks_128', x: 64, y: 128 },
  { sample: 'rock_128', x: 128, y: 128 },
  { sample: 'carpet_128', x: 32, y: 192 },
];

/** Positions are whole, non-negative and at most this (the output stays far below 8192 a side). */
const MAX_POSITION = 2048;

/** The row of source index `k` as the list's "Add image" makes it. */
export const defaultSource = (k) => ({ ...DEFAULTS[k] });

/** The exemplar and the second image, as the panel opens. */
export const DEFAULT_SOURCES = [defaultSource(0), defaultSource(1)];

export const sampleUrl = (id) => SAMPLES.find((s) => s.id === id)?.url;

const position = (value) => Math.min(MAX_POSITION, Math.max(0, Math.round(Number(value)) || 0));

/**
 * The list as one field value: `x.y` for the exemplar, then `sample.x.y` per image, joined by
 * `-` (sample ids hold neither `.` nor `-`, so a link shows the list as it reads).
 */
export function serialiseSources(sources) {
  return sources.map((s, k) => (k === 0 ? `${s.x}.${s.y}` : `${s.sample}.${s.x}.${s.y}`)).join('-');
}

/** The list a field value names; parts that name no sample are left out. */
export function parseSources(text) {
  const [first, ...rest] = String(text ?? '').split('-');
  const [x, y] = (first ?? '').split('.');
  const sources = [{ sample: null, x: position(x), y: position(y) }];
  for (const part of rest) {
    const [sample, sx, sy] = part.split('.');
    if (sampleUrl(sample) && sources.length < MAX_SOURCES) sources.push({ sample, x: position(sx), y: position(sy) });
  }
  return sources;
}

const rgb = (k) => `rgb(${COLOURS[k].join(' ')})`;

/** The rows of every source index (those past the list are hidden), then "Add image". */
export function sourceRowsHtml() {
  const choices = SAMPLES.map((s) => `<option value="${s.id}">${s.label}</option>`).join('');
  const rows = COLOURS.map((_, k) => {
    const name = k === 0 ? 'image 1 (the exemplar)' : `image ${k + 1}`;
    const picker = k === 0
      ? '<span>exemplar</span>'
      : `<select class="mg-image view" aria-label="${name}: sample">${choices}</select>`;
    const remove = k === 0 ? '' : `<button class="mg-remove" type="button" aria-label="Remove ${name}">remove</button>`;
    return `
      <div id="mg-source-${k}" data-source="${k}" role="group" aria-label="${name}"${k < 2 ? '' : ' hidden'}>
        <div style="display: flex; flex-wrap: wrap; gap: .3rem .8rem; align-items: center">
          <label title="brush: paint pixels that must come from ${name}"><input type="radio" name="mg-brush" class="view" value="${k + 1}" aria-label="brush: ${name}"${k === 0 ? ' checked' : ''}>
            <span aria-hidden="true" style="display: inline-block; width: .9em; height: .9em; border-radius: 2px; vertical-align: -.1em; background: ${rgb(k)}"></span> ${k + 1}</label>
          ${picker}
          <label title="left edge of ${name} in the merge">x <input class="mg-x view" type="number" min="0" max="${MAX_POSITION}" step="1" value="${DEFAULTS[k].x}" aria-label="${name}: x"></label>
          <label title="top edge of ${name} in the merge">y <input class="mg-y view" type="number" min="0" max="${MAX_POSITION}" step="1" value="${DEFAULTS[k].y}" aria-label="${name}: y"></label>
          ${remove}
        </div>
      </div>`;
  }).join('');
  return `
    <fieldset id="mg-sources-list" style="flex: 1 1 100%; min-width: 0; display: grid; gap: .3rem; border: 1px solid var(--line); border-radius: 6px; padding: .3rem .6rem; margin: 0">
      <legend>Images: brush colour, picture, position (x, y)</legend>
      ${rows}
      <div><button id="mg-add" type="button">Add image</button></div>
    </fieldset>`;
}

/** Shows `sources` in the rows (`$`: the page's getElementById) and greys "Add image" at 8. */
export function showSourceRows($, sources) {
  COLOURS.forEach((_, k) => {
    const row = $(`mg-source-${k}`);
    row.hidden = k >= sources.length;
    if (row.hidden) return;
    const s = sources[k];
    if (k > 0) row.querySelector('.mg-image').value = s.sample;
    row.querySelector('.mg-x').value = String(s.x);
    row.querySelector('.mg-y').value = String(s.y);
  });
  $('mg-add').disabled = sources.length >= MAX_SOURCES;
  // A brush for a source that is not in the list (one removed, or a link's) paints the first.
  const brush = document.querySelector('input[name="mg-brush"]:checked');
  if (!brush || Number(brush.value) > sources.length) document.querySelector('input[name="mg-brush"][value="1"]').checked = true;
}

/** The sources as the visible rows give them (positions whole and non-negative). */
export function readSourceRows($) {
  const sources = [];
  for (let k = 0; k < MAX_SOURCES; k++) {
    const row = $(`mg-source-${k}`);
    if (row.hidden) break;
    sources.push({
      sample: k === 0 ? null : row.querySelector('.mg-image').value,
      x: position(row.querySelector('.mg-x').value),
      y: position(row.querySelector('.mg-y').value),
    });
  }
  return sources;
}

/**
 * The output box around `placed` ({ x, y, width, height } per source, in the list's order):
 * `{ width, height, x, y, rects }`, with (x, y) the box's top-left corner in the list's
 * positions and `rects` each source's rectangle in output pixels.
 */
export function boxAround(placed) {
  const x = Math.min(...placed.map((p) => p.x));
  const y = Math.min(...placed.map((p) => p.y));
  const width = Math.max(...placed.map((p) => p.x + p.width)) - x;
  const height = Math.max(...placed.map((p) => p.y + p.height)) - y;
  const rects = placed.map((p) => ({ x: p.x - x, y: p.y - y, width: p.width, height: p.height }));
  return { width, height, x, y, rects };
}

const NEIGHBOURS = [[1, 0], [-1, 0], [0, 1], [0, -1]];

/**
 * Whether output pixel (x, y) of `box` may be painted for source `value` (1 for the first, k for
 * source k): inside that source, and not on its edge where an earlier source covers the pixel and
 * its neighbour beyond the edge. GraphcutMerge refuses other paint (check_paint in
 * src/methods/graphcut/merge.rs): the seam graph holds such an edge pixel to the composite, so
 * the cut cannot give it to the new source.
 */
export function mayPaint(box, value, x, y) {
  const k = value - 1;
  const { rects, width, height } = box;
  const inside = (j, px, py) => {
    const r = rects[j];
    return px >= r.x && py >= r.y && px < r.x + r.width && py < r.y + r.height;
  };
  const coveredBefore = (px, py) => {
    for (let j = 0; j < k; j++) if (inside(j, px, py)) return true;
    return false;
  };
  if (!rects[k] || !inside(k, x, y)) return false;
  if (!coveredBefore(x, y)) return true;
  return !NEIGHBOURS.some(([dx, dy]) => {
    const [nx, ny] = [x + dx, y + dy];
    const inOutput = nx >= 0 && ny >= 0 && nx < width && ny < height;
    return inOutput && !inside(k, nx, ny) && coveredBefore(nx, ny);
  });
}

/**
 * The paint of `mask` over box `from` carried to box `to` (null `from`: no paint yet): each
 * painted pixel stays where it is among the sources, and goes where it falls outside `to` or
 * where `mayPaint` does not allow it in `to` (its source moved, or an earlier one did).
 */
export function carryPaint(mask, from, to) {
  const moved = new Uint8Array(to.width * to.height);
  if (!mask || !from) return moved;
  const count = to.rects.length;
  for (let i = 0; i < mask.length; i++) {
    const value = mask[i];
    if (!value || value > count) continue;
    const x = (i % from.width) + from.x - to.x;
    const y = Math.floor(i / from.width) + from.y - to.y;
    if (x < 0 || y < 0 || x >= to.width || y >= to.height || !mayPaint(to, value, x, y)) continue;
    moved[y * to.width + x] = value;
  }
  return moved;
}

/** `mask` without the paint of source `value`; the paint of each later source follows it one
 * place up the list. */
export function removeFromPaint(mask, value) {
  for (let i = 0; i < mask.length; i++) {
    if (mask[i] === value) mask[i] = 0;
    else if (mask[i] > value) mask[i] -= 1;
  }
}

/** The painted pixels of `mask`, per source of the `count`. */
export function paintedPerSource(mask, count) {
  const painted = new Array(count).fill(0);
  for (const value of mask) if (value) painted[value - 1] += 1;
  return painted;
}

/** Draws the paint of `mask` into an RGBA buffer of the same size. */
export function paintInto(buffer, mask) {
  for (let i = 0; i < mask.length; i++) {
    const value = mask[i];
    if (!value) continue;
    const [r, g, b] = COLOURS[value - 1];
    buffer[i * 4] = r;
    buffer[i * 4 + 1] = g;
    buffer[i * 4 + 2] = b;
    buffer[i * 4 + 3] = PAINT_ALPHA;
  }
}
