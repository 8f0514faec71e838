// Small line plots on a canvas: values against step, with vertical markers where a level starts,
// or several series on one scale. Each canvas remembers what it last drew, so the history
// scrubber (www/lib/history.js) can redraw a panel's plot with a current-step marker without
// knowing which panel drew it.

const drawn = new WeakMap();

/** Clears `canvas`, draws the title and axes for `values` (all series together, `length` steps
 * long) and returns the maps from step and value to canvas coordinates; null when empty. */
function frame(canvas, values, length, title) {
  const ctx = canvas.getContext('2d');
  const { width, height } = canvas;
  const pad = { left: 44, right: 8, top: 18, bottom: 18 };
  ctx.clearRect(0, 0, width, height);
  ctx.fillStyle = '#101217';
  ctx.fillRect(0, 0, width, height);
  ctx.font = '11px system-ui, sans-serif';
  ctx.fillStyle = '#9aa1b2';
  ctx.fillText(title, pad.left, 12);
  if (values.length === 0) return null;
  const max = Math.max(...values);
  const min = Math.min(0, ...values);
  const span = max - min || 1;
  const x = (i) => pad.left + (length <= 1 ? 0 : (i / (length - 1)) * (width - pad.left - pad.right));
  const y = (v) => height - pad.bottom - ((v - min) / span) * (height - pad.top - pad.bottom);
  ctx.strokeStyle = '#2e3340';
  ctx.beginPath();
  ctx.moveTo(pad.left, pad.top);
  ctx.lineTo(pad.left, height - pad.bottom);
  ctx.lineTo(width - pad.right, height - pad.bottom);
  ctx.stroke();
  ctx.fillText(format(max), 2, pad.top + 4);
  ctx.fillText(format(min), 2, height - pad.bottom);
  return { ctx, x, y, pad };
}

function line(ctx, values, x, y, color) {
  ctx.strokeStyle = color;
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  values.forEach((v, i) => (i === 0 ? ctx.moveTo(x(i), y(v)) : ctx.lineTo(x(i), y(v))));
  ctx.stroke();
  ctx.lineWidth = 1;
}

/**
 * Draws `values` (numbers) on `canvas`. `markers` is a list of { index, label } drawn as dashed
 * vertical lines (level changes). Axis labels give the range.
 */
export function drawLinePlot(canvas, values, { markers = [], title = '', color = '#e0a458', current = null } = {}) {
  drawn.set(canvas, { draw: (at) => drawLinePlot(canvas, values, { markers, title, color, current: at }), length: values.length });
  const f = frame(canvas, values, values.length, title);
  if (!f) return;
  const { ctx, x, y, pad } = f;
  const { width, height } = canvas;
  ctx.fillText(`${values.length}`, width - pad.right - 16, height - 4);
  ctx.setLineDash([3, 3]);
  for (const { index, label } of markers) {
    ctx.strokeStyle = '#4a5163';
    ctx.beginPath();
    ctx.moveTo(x(index), pad.top);
    ctx.lineTo(x(index), height - pad.bottom);
    ctx.stroke();
    ctx.fillStyle = '#9aa1b2';
    ctx.fillText(label, x(index) + 2, pad.top + 10);
  }
  ctx.setLineDash([]);
  line(ctx, values, x, y, color);
  ctx.fillStyle = color;
  values.forEach((v, i) => ctx.fillRect(x(i) - 1.5, y(v) - 1.5, 3, 3));
  if (current !== null && current >= 0 && current < values.length) currentMarker(ctx, x(current), y(values[current]), pad, height);
}

/** The step the history scrubber shows: a solid vertical line and a ring on its point. */
function currentMarker(ctx, px, py, pad, height) {
  ctx.strokeStyle = '#7fd1ff';
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  ctx.moveTo(px, pad.top);
  ctx.lineTo(px, height - pad.bottom);
  ctx.stroke();
  ctx.beginPath();
  ctx.arc(px, py, 4, 0, 2 * Math.PI);
  ctx.stroke();
  ctx.lineWidth = 1;
}

/** How many points the plot last drawn on `canvas` has (for a multi-series plot: the series that
 * grows last, i.e. the one being run); 0 when nothing was drawn. */
export function plotLength(canvas) {
  return drawn.get(canvas)?.length ?? 0;
}

/** Redraws the plot last drawn on `canvas` with the current-step marker at point `index`
 * (null: no marker, the live view). Does nothing on a canvas no plot was drawn on. */
export function markPlot(canvas, index) {
  drawn.get(canvas)?.draw(index);
}

/**
 * Draws several series on one plot, each `{ values, color, label }`, on a shared scale (the
 * energy of plain, Haar and Daubechies runs, as in Fig. 5 of Shen et al. 2009).
 */
export function drawLinePlots(canvas, series, { title = '', current = null } = {}) {
  const growing = [...series].reverse().find((s) => s.values.length > 0);
  drawn.set(canvas, { draw: (at) => drawLinePlots(canvas, series, { title, current: at }), length: growing?.values.length ?? 0 });
  const longest = Math.max(0, ...series.map((s) => s.values.length));
  const f = frame(canvas, series.flatMap((s) => s.values), longest, title);
  if (!f) return;
  const { ctx, x, y, pad } = f;
  series.forEach(({ values, color, label }, k) => {
    line(ctx, values, x, y, color);
    ctx.fillStyle = color;
    ctx.fillText(label, canvas.width - pad.right - 90, pad.top + 12 * (k + 1));
  });
  if (growing && current !== null && current >= 0 && current < growing.values.length) {
    currentMarker(ctx, x(current), y(growing.values[current]), pad, canvas.height);
  }
}

function format(v) {
  return Math.abs(v) >= 100 || v === 0 ? v.toFixed(0) : v.toPrecision(2);
}
