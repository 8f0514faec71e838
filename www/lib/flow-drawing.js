// A flow field drawn by hand. Kwatra et al. 2005 drew their flows interactively (section 4.1);
// here a stroke is a polyline in shares of the frame (0 to 1 across and down), and each pixel's
// flow is the average of the strokes' directions, each segment weighted by how near it passes:
// w = 1 / (r^2 + s^2)^2, r the distance to the segment, s a tenth of the frame. Near one stroke
// the flow follows it at full strength; between strokes that disagree it is weaker; far from
// all of them it takes the nearest ones' direction. Strength is in pixels per frame.

const SOFTNESS = 0.1;

/** The (vx, vy) field of `strokes` for a `width` x `height` frame, as `FlowAnimation` takes it. */
export function fieldFromStrokes(strokes, width, height, strength) {
  const segments = [];
  for (const points of strokes) {
    for (let i = 1; i < points.length; i++) {
      const [ax, ay] = points[i - 1];
      const [bx, by] = points[i];
      const length = Math.hypot(bx - ax, by - ay);
      if (length > 0) segments.push({ ax, ay, bx, by, length, dx: (bx - ax) / length, dy: (by - ay) / length });
    }
  }
  const field = new Float32Array(width * height * 2);
  if (segments.length === 0) return field;
  const s2 = SOFTNESS * SOFTNESS;
  for (let y = 0; y < height; y++) {
    const py = (y + 0.5) / height;
    for (let x = 0; x < width; x++) {
      const px = (x + 0.5) / width;
      let sx = 0;
      let sy = 0;
      let sw = 0;
      for (const g of segments) {
        // The nearest point of the segment.
        const t = Math.min(1, Math.max(0, ((px - g.ax) * g.dx + (py - g.ay) * g.dy) / g.length));
        const qx = g.ax + t * (g.bx - g.ax) - px;
        const qy = g.ay + t * (g.by - g.ay) - py;
        const d = qx * qx + qy * qy + s2;
        const w = g.length / (d * d);
        sx += w * g.dx;
        sy += w * g.dy;
        sw += w;
      }
      const i = (y * width + x) * 2;
      field[i] = (strength * sx) / sw;
      field[i + 1] = (strength * sy) / sw;
    }
  }
  return field;
}
