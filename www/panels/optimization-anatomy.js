// The step anatomy of the texture-optimization panel (Kwatra et al. 2005, section 3): each EM
// iteration split into its halves. After the E-step the output is x, the IRLS-weighted average of
// the matched neighbourhoods (section 3.1); after the M-step it is shown as what the M-step chose: the
// nearest exemplar neighbourhood z_p of every grid node, pasted where the node is. Beside it: the
// z_p drawn on the exemplar in the colour of the node they serve, and the IRLS weights
// ||x_p - z_p||^(r-2) as a heat map. The data is the session's field() (grid, matches,
// distances, weights). The flow panel shows the same views for the EM iterations of its frames
// (section 4.1), with the warped previous frame they are pulled towards first.

import { heat, paintGrid } from '../lib/heat.js';

/**
 * The step anatomy's side views; `before` is markup a panel puts first in the section (the flow
 * panel's warped previous frame, the constraint target its E-steps are pulled towards).
 */
export const stepAnatomyHtml = (before = '') => `
  <section class="anatomy" id="to-anatomy" hidden aria-label="Step anatomy">${before}
    <h3>Chosen neighbourhoods z<sub>p</sub> on the exemplar</h3>
    <canvas id="to-matches" class="anatomy-graph" width="296" height="296" aria-label="Matched exemplar neighbourhoods"></canvas>
    <p class="legend">Each square is the z<sub>p</sub> of one grid node, in the colour of where that node sits on the
      output (left to right: red to blue; top to bottom: dark to light). Hover the output to follow one node.</p>
    <h3>IRLS weights <small>||x<sub>p</sub> − z<sub>p</sub>||<sup>r−2</sup>, section 3.1</small></h3>
    <canvas id="to-weights" class="anatomy-graph" width="296" height="296" aria-label="IRLS weight of each node"></canvas>
    <p class="legend">Bright: a node that matches well and pulls hard in the next E-step; dark: an outlier the robust
      weights quiet down (r &lt; 2).</p>
    <p class="readout" id="to-node-readout" aria-live="polite">hover the output for a node</p>
  </section>`;

export const STEP_ANATOMY_HTML = stepAnatomyHtml();

/** Colour of the node in column i of `columns`, row j of `rows`: hue across, lightness down. */
function nodeColour(i, columns, j, rows) {
  const hue = Math.round((i / Math.max(1, columns - 1)) * 240);
  const light = Math.round(35 + (j / Math.max(1, rows - 1)) * 35);
  return `hsl(${hue} 85% ${light}%)`;
}

/**
 * The M-step's picture: the z_p of every fourth node in each direction (their neighbourhoods,
 * spaced w/4 apart, tile the level without overlap) copied from the exemplar canvas onto `canvas`
 * at the output's size, with the neighbourhood grid outlined.
 */
export function drawCollage(canvas, field, exemplarCanvas, width, height) {
  canvas.width = width;
  canvas.height = height;
  const ctx = canvas.getContext('2d');
  ctx.imageSmoothingEnabled = false;
  ctx.fillStyle = '#000';
  ctx.fillRect(0, 0, width, height);
  const w = field.neighbourhoodSize;
  const ox = width / field.levelWidth;
  const oy = height / field.levelHeight;
  const ex = exemplarCanvas.width / field.exemplarWidth;
  const ey = exemplarCanvas.height / field.exemplarHeight;
  const cols = field.columns.length;
  field.rows.forEach((y, j) => {
    if (j % 4 && j !== field.rows.length - 1) return;
    field.columns.forEach((x, i) => {
      if (i % 4 && i !== cols - 1) return;
      const n = j * cols + i;
      const [mx, my] = [field.matches[2 * n], field.matches[2 * n + 1]];
      ctx.drawImage(exemplarCanvas, mx * ex, my * ey, w * ex, w * ey, x * ox, y * oy, w * ox, w * oy);
    });
  });
}

/** The z_p of every node as a square on the exemplar, coloured by the node; `node` highlighted. */
export function drawMatches(canvas, field, exemplarCanvas, node = -1) {
  const zoom = Math.min(296 / exemplarCanvas.width, 296 / exemplarCanvas.height);
  canvas.width = Math.round(exemplarCanvas.width * zoom);
  canvas.height = Math.round(exemplarCanvas.height * zoom);
  const ctx = canvas.getContext('2d');
  ctx.globalAlpha = 0.55;
  ctx.drawImage(exemplarCanvas, 0, 0, canvas.width, canvas.height);
  ctx.globalAlpha = 1;
  const sx = canvas.width / field.exemplarWidth;
  const sy = canvas.height / field.exemplarHeight;
  const w = field.neighbourhoodSize;
  const cols = field.columns.length;
  const rows = field.rows.length;
  ctx.lineWidth = 1;
  for (let n = 0; n < cols * rows; n++) {
    const [mx, my] = [field.matches[2 * n], field.matches[2 * n + 1]];
    ctx.strokeStyle = nodeColour(n % cols, cols, Math.floor(n / cols), rows);
    // Centres as dots (all nodes), so that dense grids stay readable.
    ctx.fillStyle = ctx.strokeStyle;
    ctx.fillRect((mx + w / 2) * sx - 1.5, (my + w / 2) * sy - 1.5, 3, 3);
  }
  if (node >= 0) {
    const [mx, my] = [field.matches[2 * node], field.matches[2 * node + 1]];
    ctx.strokeStyle = '#ffffff';
    ctx.lineWidth = 2;
    ctx.strokeRect(mx * sx, my * sy, w * sx, w * sy);
  }
}

/** The IRLS weight of every node as a heat map over the grid (grey before the first M-step). */
export function drawWeights(canvas, field) {
  const cols = field.columns.length;
  const rows = field.rows.length;
  const zoom = Math.max(1, Math.floor(Math.min(296 / cols, 296 / rows)));
  canvas.width = cols * zoom;
  canvas.height = rows * zoom;
  const finite = Array.from(field.weights).filter(Number.isFinite).sort((a, b) => a - b);
  const lo = finite[0] ?? 0;
  const hi = finite[Math.floor(0.95 * (finite.length - 1))] ?? 1;
  paintGrid(canvas, cols, rows, (n) => {
    const v = field.weights[n];
    return Number.isFinite(v) ? heat((v - lo) / (hi - lo || 1)) : [70, 72, 80];
  });
  return { lo, hi, nodes: finite.length };
}

/** The grid node whose neighbourhood centre is nearest output pixel (x, y) of an output
 * `width` x `height`, as its index. */
export function nodeAt(field, x, y, width, height) {
  const lx = (x / width) * field.levelWidth;
  const ly = (y / height) * field.levelHeight;
  const half = field.neighbourhoodSize / 2;
  const nearest = (list, v) => list.reduce((best, c, i) => (Math.abs(c + half - v) < Math.abs(list[best] + half - v) ? i : best), 0);
  return nearest(field.rows, ly) * field.columns.length + nearest(field.columns, lx);
}

/** The grid node under pointer `event` on `canvas`, which shows a `width` x `height` output. */
export function nodeUnderPointer(event, canvas, field, width, height) {
  const rect = canvas.getBoundingClientRect();
  const x = ((event.clientX - rect.left) / rect.width) * width;
  const y = ((event.clientY - rect.top) / rect.height) * height;
  return nodeAt(field, x, y, width, height);
}

/**
 * The side views of a step: the z_p on the exemplar, the IRLS weights (their node count left on
 * the weights canvas for tests) and the hovered node's readout.
 */
export function drawSideViews({ matches, weights, readout }, field, exemplarCanvas, node) {
  drawMatches(matches, field, exemplarCanvas, node);
  weights.dataset.nodes = String(drawWeights(weights, field).nodes);
  if (node >= 0) readout.textContent = describeNode(field, node);
}

/** Outlines node `n`'s neighbourhood on the output canvas (drawn at the output's size). */
export function outlineNode(canvas, field, n) {
  const cols = field.columns.length;
  const ox = canvas.width / field.levelWidth;
  const oy = canvas.height / field.levelHeight;
  const w = field.neighbourhoodSize;
  const ctx = canvas.getContext('2d');
  ctx.strokeStyle = '#ffffff';
  ctx.lineWidth = 2;
  ctx.strokeRect(field.columns[n % cols] * ox, field.rows[Math.floor(n / cols)] * oy, w * ox, w * oy);
}

/** What the readout says about node `n`. */
export function describeNode(field, n) {
  const cols = field.columns.length;
  const [x, y] = [field.columns[n % cols], field.rows[Math.floor(n / cols)]];
  const [mx, my] = [field.matches[2 * n], field.matches[2 * n + 1]];
  const d = field.distances[n];
  const weight = field.weights[n];
  const figures = Number.isFinite(d)
    ? `||x_p − z_p|| = ${d.toFixed(3)}, IRLS weight ${weight.toPrecision(3)} (r = ${Number(field.r.toFixed(3))})`
    : 'no M-step on this level yet';
  return `node (${x}, ${y}) of the level's grid, ${field.neighbourhoodSize}×${field.neighbourhoodSize}: ` +
    `z_p at exemplar (${mx}, ${my}); ${figures}`;
}
