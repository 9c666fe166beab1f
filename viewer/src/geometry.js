// Table geometry for drawing (include/cueball/table.hpp) and the mapping from
// table metres to canvas pixels.
//
// Table frame: x along the length (0..length), y across (0..width), origin at
// the bottom-left corner of the playing surface, drawn with x to the right and
// y UP (the canvas y axis is flipped).

const JAW_TOLERANCE = 1e-6; // m: a jaw joins two cushion ends lying on its circle

/**
 * The closed outline of the cushion noses, counter-clockwise around the
 * playing surface: each cushion's nose line, joined to the next one by the
 * jaw arc tangent to both, or straight across a pocket mouth.
 * @returns {({kind:'line', from:number[], to:number[]}|{kind:'arc', centre:number[], radius:number, a0:number, a1:number})[]}
 */
export function noseOutline(table) {
  const cushions = table.cushions || [];
  const jaws = table.jaws || [];
  const out = [];
  cushions.forEach((c, i) => {
    out.push({ kind: 'line', from: c.start, to: c.end });
    const next = cushions[(i + 1) % cushions.length];
    const a = c.end;
    const b = next.start;
    if (Math.hypot(b[0] - a[0], b[1] - a[1]) <= JAW_TOLERANCE) return;
    const jaw = jaws.find((j) => onCircle(j, a) && onCircle(j, b));
    if (jaw) {
      const a0 = Math.atan2(a[1] - jaw.centre[1], a[0] - jaw.centre[0]);
      let a1 = Math.atan2(b[1] - jaw.centre[1], b[0] - jaw.centre[0]);
      // the short way round: a jaw turns the nose by less than half a turn
      while (a1 - a0 > Math.PI) a1 -= 2 * Math.PI;
      while (a1 - a0 < -Math.PI) a1 += 2 * Math.PI;
      out.push({ kind: 'arc', centre: jaw.centre, radius: jaw.radius, a0, a1 });
    } else {
      out.push({ kind: 'line', from: a, to: b }); // across a pocket mouth
    }
  });
  return out;
}

function onCircle(jaw, p) {
  const d = Math.hypot(p[0] - jaw.centre[0], p[1] - jaw.centre[1]);
  return Math.abs(d - jaw.radius) <= JAW_TOLERANCE + 1e-6 * jaw.radius;
}

/**
 * Distances outside the playing surface (m) of the cushion backs (where the
 * wooden rail starts) and of the rail's outer edge, and the whole drawn area.
 */
export function tableLayout(table, ballRadius) {
  const { length, width } = table;
  const beyond = (p) => Math.max(-p[0], p[0] - length, -p[1], p[1] - width, 0);
  let cushionBack = 1.6 * ballRadius;
  for (const c of table.cushions || []) cushionBack = Math.max(cushionBack, beyond(c.start), beyond(c.end));
  let railOuter = cushionBack + 0.09;
  for (const d of table.diamonds || []) railOuter = Math.max(railOuter, beyond(d) + 0.05);
  for (const p of table.pockets || []) railOuter = Math.max(railOuter, beyond(p.centre) + p.radius + 0.03);
  return {
    length,
    width,
    cushionBack,
    railOuter,
    outline: noseOutline(table),
    extent: { x0: -railOuter, y0: -railOuter, x1: length + railOuter, y1: width + railOuter },
  };
}

/**
 * Fits the drawn area into a canvas of cssWidth x cssHeight CSS pixels,
 * keeping the aspect ratio, and maps between table metres and pixels.
 */
export class View {
  constructor(extent, cssWidth, cssHeight, dpr = 1, padding = 8) {
    const w = extent.x1 - extent.x0;
    const h = extent.y1 - extent.y0;
    this.cssWidth = cssWidth;
    this.cssHeight = cssHeight;
    this.dpr = dpr;
    this.scale = Math.max(1e-6, Math.min((cssWidth - 2 * padding) / w, (cssHeight - 2 * padding) / h));
    // centre the drawn area; ox, oy: CSS pixel of the table origin
    this.ox = (cssWidth - w * this.scale) / 2 - extent.x0 * this.scale;
    this.oy = (cssHeight + h * this.scale) / 2 + extent.y0 * this.scale;
  }

  /** CSS pixel [x, y] (from the canvas's top-left) of a point on the table. */
  toCss(x, y) {
    return [this.ox + x * this.scale, this.oy - y * this.scale];
  }

  /** Table point [x, y] under a CSS pixel. */
  toTable(px, py) {
    return [(px - this.ox) / this.scale, (this.oy - py) / this.scale];
  }

  /** Draw in table metres, y up. */
  applyTable(ctx) {
    const k = this.dpr * this.scale;
    ctx.setTransform(k, 0, 0, -k, this.dpr * this.ox, this.dpr * this.oy);
  }

  /** Draw in CSS pixels. */
  applyCss(ctx) {
    ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
  }

  /** Metres spanned by n CSS pixels (line widths while drawing in metres). */
  metres(n) {
    return n / this.scale;
  }
}

/** Adds the outline to the current path (in table metres). */
export function traceOutline(ctx, outline) {
  outline.forEach((piece, i) => {
    if (piece.kind === 'line') {
      if (i === 0) ctx.moveTo(piece.from[0], piece.from[1]);
      else ctx.lineTo(piece.from[0], piece.from[1]);
      ctx.lineTo(piece.to[0], piece.to[1]);
    } else {
      ctx.arc(piece.centre[0], piece.centre[1], piece.radius, piece.a0, piece.a1, piece.a1 < piece.a0);
    }
  });
  ctx.closePath();
}
