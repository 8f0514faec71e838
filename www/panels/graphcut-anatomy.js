// The placement anatomy of the graph-cut panel (Kwatra et al. 2003): for the placement just made,
// the cost surface C(t) of eq. 2 (or eq. 4) over every candidate offset with the drawn offset
// marked, the probability exp(-C / (k sigma^2)) of eq. 3 that drew it, and the graph of section 3
// whose minimum cut is the seam. The data comes from the session's placementCosts() and
// placementGraph() (recorded only while this view is on, see setAnatomy).

import { heat, paintGrid } from '../lib/heat.js';

export const ANATOMY_HTML = `
  <section class="anatomy" id="gc-anatomy" hidden aria-label="Placement anatomy">
    <h3>Where could the patch go? <small>C(t), eq. 2</small></h3>
    <canvas id="gc-cost" class="anatomy-map" width="148" height="148" aria-label="Cost surface over candidate offsets"></canvas>
    <canvas id="gc-probability" class="anatomy-map" width="148" height="148" aria-label="Probability of each offset"></canvas>
    <p class="legend" id="gc-cost-legend">Left: matching cost of every unused offset that covers the error region (dark: low).
      Right: the chance eq. 3 gives each (bright: likely). Cyan ring: the offset drawn; white square: the cheapest.</p>
    <h3>The graph whose cut is the seam <small>section 3, 3.1</small></h3>
    <canvas id="gc-graph" class="anatomy-graph" width="296" height="296" aria-label="Seam graph of the placement"></canvas>
    <p class="legend">Colour: capacity of each pixel's arcs M(s, t, A, B) (dark: cheap to cut), lit where
      the new patch B was taken and dimmed where the old output A was kept. Blue: held to A (the border);
      orange: held to B; grey: uncovered (takes B, no node); red: an old seam (a seam node, section 3.1);
      white line: the minimum cut, the new seam.</p>
    <p class="readout" id="gc-graph-readout" aria-live="polite">hover the graph for a pixel's arcs</p>
  </section>`;

/** The value below which `q` of the finite `values` lie. */
function quantile(values, q) {
  const finite = Array.from(values).filter(Number.isFinite).sort((a, b) => a - b);
  return finite.length ? finite[Math.min(finite.length - 1, Math.floor(q * finite.length))] : 0;
}

/** Draws the cost surface and the probability map; returns figures the page and tests read. */
export function drawCosts(costCanvas, probabilityCanvas, c) {
  const { width, height, cost, probability } = c;
  const low = Math.min(...Array.from(cost).filter(Number.isFinite));
  // The 90th percentile as the top of the scale: a few very bad offsets would flatten the rest.
  const high = quantile(cost, 0.9);
  const cell = (x, y, canvas) => [(x + 0.5) * (canvas.width / width), (y + 0.5) * (canvas.height / height)];
  const costCtx = paintGrid(costCanvas, width, height, (k) =>
    Number.isFinite(cost[k]) ? heat((cost[k] - low) / (high - low || 1)) : [60, 62, 70]);
  const pMax = Math.max(...probability);
  const probCtx = paintGrid(probabilityCanvas, width, height, (k) => heat(Math.sqrt(probability[k] / (pMax || 1))));
  const best = Array.from(cost).indexOf(low);
  for (const [ctx, canvas] of [[costCtx, costCanvas], [probCtx, probabilityCanvas]]) {
    const [bx, by] = cell(best % width, Math.floor(best / width), canvas);
    ctx.strokeStyle = '#ffffff';
    ctx.lineWidth = 1.5;
    ctx.strokeRect(bx - 4, by - 4, 8, 8);
    if (c.chosenX >= 0) {
      const [x, y] = cell(c.chosenX, c.chosenY, canvas);
      ctx.strokeStyle = '#3ee0ff';
      ctx.lineWidth = 2;
      ctx.beginPath();
      ctx.arc(x, y, 6, 0, 2 * Math.PI);
      ctx.stroke();
    }
  }
  const chosen = c.chosenX >= 0 ? cost[c.chosenY * width + c.chosenX] : NaN;
  const finite = Array.from(cost).filter(Number.isFinite);
  return {
    offsets: finite.length,
    best: low,
    chosen,
    // Share of offsets cheaper than the one drawn: 0 when the cheapest was drawn.
    chosenRank: finite.filter((v) => v < chosen).length / finite.length,
    chosenProbability: c.chosenX >= 0 ? probability[c.chosenY * width + c.chosenX] : 0,
    // Offsets eq. 3 could draw (feature-guided placement draws among the best by colour only).
    drawable: Array.from(probability).filter((p) => p > 0).length,
  };
}

const KIND_TINT = { 1: [95, 98, 108], 3: [60, 120, 230], 4: [240, 150, 40] };

/** Draws the seam graph: capacities as a heat map (the side that took the new patch brighter),
 * kinds in solid colours, old seams red, and the minimum cut as white lines between pixels. */
export function drawGraph(canvas, g) {
  const { width, height, kind, right, down, oldRight, oldDown, taken } = g;
  const capacity = (k) => Math.max(Number.isNaN(right[k]) ? 0 : right[k], Number.isNaN(down[k]) ? 0 : down[k]);
  const caps = Array.from({ length: width * height }, (_, k) => capacity(k));
  const high = quantile(caps.filter((v, k) => kind[k] >= 2), 0.95) || 1;
  const zoom = Math.max(1, Math.floor(Math.min(296 / width, 296 / height)));
  canvas.width = width * zoom;
  canvas.height = height * zoom;
  const ctx = paintGrid(canvas, width, height, (k) => {
    if (kind[k] === 0) return [16, 18, 23];
    if (!Number.isNaN(oldRight[k]) || !Number.isNaN(oldDown[k])) return [230, 40, 40];
    if (KIND_TINT[kind[k]]) return KIND_TINT[kind[k]];
    // Kept pixels dimmed, so the region the new patch took reads as the lit one.
    const warm = heat(caps[k] / high);
    return taken[k] ? warm : warm.map((v) => Math.round(v * 0.45));
  });
  // The cut runs between two pixels in the graph (nodes, or a node and an uncovered pixel) that
  // ended on different sides.
  const inGraph = (k) => kind[k] !== 0;
  ctx.strokeStyle = '#ffffff';
  ctx.lineWidth = Math.max(1.5, zoom * 0.75);
  ctx.beginPath();
  let cutPixels = 0;
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const k = y * width + x;
      if (!inGraph(k)) continue;
      if (x + 1 < width && inGraph(k + 1) && taken[k] !== taken[k + 1]) {
        ctx.moveTo((x + 1) * zoom, y * zoom);
        ctx.lineTo((x + 1) * zoom, (y + 1) * zoom);
        cutPixels++;
      }
      if (y + 1 < height && inGraph(k + width) && taken[k] !== taken[k + width]) {
        ctx.moveTo(x * zoom, (y + 1) * zoom);
        ctx.lineTo((x + 1) * zoom, (y + 1) * zoom);
        cutPixels++;
      }
    }
  }
  ctx.stroke();
  const count = (k) => kind.filter((v) => v === k).length;
  return { zoom, cutPixels, keepOld: count(3), takeNew: count(4) };
}

/** What the graph readout says about the pixel under the pointer. */
export function describePixel(g, x, y) {
  if (x < 0 || y < 0 || x >= g.width || y >= g.height) return '';
  const k = y * g.width + x;
  const names = ['outside the output', 'uncovered: takes the new patch, no node', 'free node',
    'held to the old output A', 'held to the new patch B'];
  const arc = (v) => (Number.isNaN(v) ? '—' : v.toFixed(4));
  const seam = (v) => (Number.isNaN(v) ? '' : ` (old seam ${v.toFixed(4)})`);
  return `pixel (${g.x + x}, ${g.y + y}): ${names[g.kind[k]]}; arc right ${arc(g.right[k])}${seam(g.oldRight[k])}, ` +
    `arc down ${arc(g.down[k])}${seam(g.oldDown[k])}; ${g.taken[k] ? 'took the new patch' : 'kept the old output'}`;
}

/**
 * Draws a placement's anatomy into the section of ANATOMY_HTML (`$` finds its elements by id),
 * leaves its figures as data attributes for tests, and makes the graph hoverable.
 */
export function showPlacementAnatomy($, surface, graph) {
  if (surface) {
    const f = drawCosts($('gc-cost'), $('gc-probability'), surface);
    Object.assign($('gc-cost-legend').dataset, {
      chosenRank: String(f.chosenRank), chosenProbability: String(f.chosenProbability), offsets: String(f.offsets),
      drawable: String(f.drawable),
    });
  }
  if (graph) {
    const f = drawGraph($('gc-graph'), graph);
    Object.assign($('gc-graph').dataset, { cutPixels: String(f.cutPixels), keepOld: String(f.keepOld), takeNew: String(f.takeNew) });
    $('gc-graph').onpointermove = (e) => {
      const rect = e.currentTarget.getBoundingClientRect();
      const x = Math.floor(((e.clientX - rect.left) / rect.width) * graph.width);
      const y = Math.floor(((e.clientY - rect.top) / rect.height) * graph.height);
      $('gc-graph-readout').textContent = describePixel(graph, x, y);
    };
  }
}
