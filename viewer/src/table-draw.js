// Draws the table to scale: wooden rail, cushion rubber (between the nose
// line and the rail), cloth, pockets, jaws (the arcs of the nose outline),
// diamonds and the spots and lines of the game.

import { traceOutline } from './geometry.js';

/** Colours of the table for a table name. */
export function tableTheme(name) {
  const n = String(name).toLowerCase();
  if (n.includes('snooker')) return { cloth: '#1b7a3e', cushion: '#136031', nose: '#2f9a57', wood: '#5a3620' };
  if (n.includes('carom')) return { cloth: '#2b6cb3', cushion: '#215a96', nose: '#4a8ad0', wood: '#4b3323' };
  return { cloth: '#2463a8', cushion: '#1b4f88', nose: '#4583c8', wood: '#5b3a24' };
}

/**
 * Draws the static table into ctx (a canvas of the view's size).
 * @param {CanvasRenderingContext2D} ctx
 * @param {ReturnType<import('./geometry.js').tableLayout>} layout
 * @param {import('./geometry.js').View} view
 */
export function drawTable(ctx, table, layout, view, theme) {
  const { length: L, width: W, cushionBack: cb, railOuter: ro } = layout;
  const m = (px) => view.metres(px);
  ctx.save();
  view.applyTable(ctx);

  // wooden rail
  roundedRect(ctx, -ro, -ro, L + 2 * ro, W + 2 * ro, 0.35 * (ro - cb));
  const wood = ctx.createLinearGradient(0, -ro, 0, W + ro);
  wood.addColorStop(0, shade(theme.wood, -0.15));
  wood.addColorStop(0.5, theme.wood);
  wood.addColorStop(1, shade(theme.wood, 0.12));
  ctx.fillStyle = wood;
  ctx.fill();
  ctx.lineWidth = m(1);
  ctx.strokeStyle = 'rgba(0, 0, 0, 0.6)';
  ctx.stroke();

  // cushion rubber: from the rail's inner edge to the nose line
  ctx.beginPath();
  ctx.rect(-cb, -cb, L + 2 * cb, W + 2 * cb);
  ctx.fillStyle = theme.cushion;
  ctx.fill();

  // cloth inside the nose outline
  ctx.beginPath();
  if (layout.outline.length > 0) traceOutline(ctx, layout.outline);
  else ctx.rect(0, 0, L, W);
  const light = ctx.createRadialGradient(L / 2, W / 2, 0, L / 2, W / 2, Math.hypot(L, W) / 2);
  light.addColorStop(0, shade(theme.cloth, 0.06));
  light.addColorStop(1, shade(theme.cloth, -0.08));
  ctx.fillStyle = light;
  ctx.fill();
  ctx.lineWidth = m(1.2);
  ctx.strokeStyle = theme.nose;
  ctx.stroke();

  drawMarkings(ctx, table, layout, m);

  // pockets: the hole in the slate, with a leather liner around it
  for (const p of table.pockets || []) {
    ctx.beginPath();
    ctx.arc(p.centre[0], p.centre[1], p.radius * 1.12, 0, 2 * Math.PI);
    ctx.fillStyle = '#2a1a10';
    ctx.fill();
    ctx.beginPath();
    ctx.arc(p.centre[0], p.centre[1], p.radius, 0, 2 * Math.PI);
    const hole = ctx.createRadialGradient(p.centre[0], p.centre[1], 0, p.centre[0], p.centre[1], p.radius);
    hole.addColorStop(0, '#000');
    hole.addColorStop(1, '#151515');
    ctx.fillStyle = hole;
    ctx.fill();
  }

  // jaws: the rounded cushion tips, outlined over the liner
  ctx.lineWidth = m(1.2);
  ctx.strokeStyle = theme.nose;
  for (const piece of layout.outline) {
    if (piece.kind !== 'arc') continue;
    ctx.beginPath();
    ctx.arc(piece.centre[0], piece.centre[1], piece.radius, piece.a0, piece.a1, piece.a1 < piece.a0);
    ctx.stroke();
  }

  // diamonds (sights) on the rail
  const d = Math.max(m(3), 0.009);
  ctx.fillStyle = '#efe6cf';
  for (const [x, y] of table.diamonds || []) {
    const acrossEnd = x < 0 || x > L; // sights on the end rails point across the table
    const [a, b] = acrossEnd ? [0.6 * d, d] : [d, 0.6 * d];
    ctx.beginPath();
    ctx.moveTo(x - a, y);
    ctx.lineTo(x, y + b);
    ctx.lineTo(x + a, y);
    ctx.lineTo(x, y - b);
    ctx.closePath();
    ctx.fill();
  }
  ctx.restore();
}

// Spots and lines of the game (rack.cpp): snooker baulk line, D and spots;
// pool head and foot spots.
function drawMarkings(ctx, table, layout, m) {
  const { length: L, width: W } = layout;
  const name = String(table.name).toLowerCase();
  ctx.save();
  ctx.strokeStyle = 'rgba(255, 255, 255, 0.45)';
  ctx.fillStyle = 'rgba(255, 255, 255, 0.55)';
  ctx.lineWidth = m(1);
  const spot = (x, y) => {
    ctx.beginPath();
    ctx.arc(x, y, Math.max(m(1.5), 0.004), 0, 2 * Math.PI);
    ctx.fill();
  };
  if (name.includes('snooker')) {
    // WPBSA proportions, scaled like rack.cpp snooker_spots()
    const along = L / 3.569;
    const baulk = 0.737 * along;
    const dRadius = 0.292 * (W / 1.778);
    ctx.beginPath();
    ctx.moveTo(baulk, 0);
    ctx.lineTo(baulk, W);
    ctx.moveTo(baulk, W / 2 + dRadius);
    ctx.arc(baulk, W / 2, dRadius, Math.PI / 2, (3 * Math.PI) / 2);
    ctx.stroke();
    const blue = L / 2;
    for (const [x, y] of [
      [baulk, W / 2],
      [baulk, W / 2 - dRadius],
      [baulk, W / 2 + dRadius],
      [blue, W / 2],
      [(blue + L) / 2, W / 2],
      [L - 0.324 * along, W / 2],
    ]) {
      spot(x, y);
    }
  } else if (name.includes('pool')) {
    spot(0.25 * L, W / 2);
    spot(0.75 * L, W / 2);
  }
  ctx.restore();
}

function roundedRect(ctx, x, y, w, h, r) {
  ctx.beginPath();
  ctx.moveTo(x + r, y);
  ctx.arcTo(x + w, y, x + w, y + h, r);
  ctx.arcTo(x + w, y + h, x, y + h, r);
  ctx.arcTo(x, y + h, x, y, r);
  ctx.arcTo(x, y, x + w, y, r);
  ctx.closePath();
}

/** Lightens (k > 0) or darkens (k < 0) a #rrggbb colour. */
export function shade(hex, k) {
  const n = parseInt(hex.slice(1), 16);
  const c = [(n >> 16) & 255, (n >> 8) & 255, n & 255].map((v) =>
    Math.round(k >= 0 ? v + (255 - v) * k : v * (1 + k)),
  );
  return `rgb(${c[0]}, ${c[1]}, ${c[2]})`;
}
