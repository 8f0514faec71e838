// Small line plots on a canvas: values against step, with vertical markers where a level starts,
// or several series on one scale.

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
export function drawLinePlot(canvas, values, { markers = [], title = '', color = '#e0a458' } = {}) {
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
}

/**
 * Draws several series on one plot, each `{ values, color, label }`, on a shared scale (the
 * energy of plain, Haar and Daubechies runs, as in Fig. 5 of Shen et al. 2009).
 */
export function drawLinePlots(canvas, series, { title = '' } = {}) {
  const longest = Math.max(0, ...series.map((s) => s.values.length));
  const f = frame(canvas, series.flatMap((s) => s.values), longest, title);
  if (!f) return;
  const { ctx, x, y, pad } = f;
  series.forEach(({ values, color, label }, k) => {
    line(ctx, values, x, y, color);
    ctx.fillStyle = color;
    ctx.fillText(label, canvas.width - pad.right - 90, pad.top + 12 * (k + 1));
  });
}

function format(v) {
  return Math.abs(v) >= 100 || v === 0 ? v.toFixed(0) : v.toPrecision(2);
}
