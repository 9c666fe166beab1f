// Ball appearance (colours by name: pool numbers, snooker colours, carom) and
// drawing to scale on the table.

const POOL_COLOURS = [
  null,
  '#f4c20d', // 1 yellow
  '#1b4fb3', // 2 blue
  '#d7261e', // 3 red
  '#5c2d91', // 4 purple
  '#f07c12', // 5 orange
  '#0f7a3d', // 6 green
  '#7d1f1f', // 7 maroon
  '#121212', // 8 black
];

const NAMED_COLOURS = {
  cue: '#f5f2e8',
  white: '#f5f2e8',
  red: '#c8161d',
  yellow: '#f3d01c',
  green: '#157a3a',
  brown: '#7a4a1f',
  blue: '#1d50c0',
  pink: '#f39ab8',
  black: '#121212',
};

const NEUTRAL = '#b9b2a0';

/** The white of a stripe's caps and number discs. */
const STRIPE_WHITE = '#fbfaf5';

/**
 * Proportions of a pool ball drawn with radius r px (fractions of r): the
 * stripe's half band, the number disc's radius, the label's font size (one
 * digit, two digits). Small balls (the whole table in a window: r of 6 to 10
 * px) get a larger disc and figures, as large as the ball allows, so the
 * number stays readable; from r = 14 px on, the proportions of a real ball
 * (disc about 0.45 of the radius, band about half the ball's height).
 */
export function ballLook(r) {
  const k = Math.min(1, Math.max(0, (r - 8) / 6)); // 0 at r <= 8 px, 1 at r >= 14 px
  const mix = (small, large) => small + (large - small) * k;
  return { band: mix(0.5, 0.52), disc: mix(0.66, 0.46), font1: mix(1.1, 0.72), font2: mix(0.92, 0.6) };
}

/**
 * How a ball looks: base colour, stripe, and the label drawn on it.
 * @returns {{colour:string, stripe:boolean, label:string, disc:boolean}}
 */
export function ballStyle(name) {
  const n = String(name);
  if (/^\d+$/.test(n)) {
    const k = Number(n);
    if (k >= 1 && k <= 8) return { colour: POOL_COLOURS[k], stripe: false, label: n, disc: true };
    if (k >= 9 && k <= 15) return { colour: POOL_COLOURS[k - 8], stripe: true, label: n, disc: true };
  }
  const lower = n.toLowerCase();
  if (lower in NAMED_COLOURS) return { colour: NAMED_COLOURS[lower], stripe: false, label: '', disc: false };
  const red = /^red(\d+)$/.exec(lower);
  if (red) return { colour: NAMED_COLOURS.red, stripe: false, label: '', disc: false };
  return { colour: NEUTRAL, stripe: false, label: n.length > 3 ? n.slice(0, 3) : n, disc: false };
}

/** A colour for lines of this ball on the cloth (trails, plot legend). */
export function trailColour(style) {
  // black is invisible on dark cloth: draw its trail grey
  return style.colour === '#121212' ? '#9a9a9a' : style.colour;
}

/**
 * Draws a ball at CSS pixel (cx, cy) with radius r px (the context in CSS
 * pixels). alpha < 1 fades it (a ball dropping into a pocket).
 */
export function drawBall(ctx, style, cx, cy, r, { alpha = 1, selected = false } = {}) {
  ctx.save();
  ctx.globalAlpha = alpha;
  // shadow on the cloth
  ctx.beginPath();
  ctx.arc(cx + 0.12 * r, cy + 0.16 * r, r, 0, 2 * Math.PI);
  ctx.fillStyle = 'rgba(0, 0, 0, 0.28)';
  ctx.fill();

  ctx.beginPath();
  ctx.arc(cx, cy, r, 0, 2 * Math.PI);
  ctx.fillStyle = style.stripe ? STRIPE_WHITE : style.colour;
  ctx.fill();
  const look = ballLook(r);
  if (style.stripe) {
    // the band across the middle, narrow enough that the white caps above
    // and below it show (a stripe is white with a coloured band; the solid
    // of the same colour is coloured all over)
    ctx.save();
    ctx.clip();
    ctx.fillStyle = style.colour;
    ctx.fillRect(cx - r, cy - look.band * r, 2 * r, 2 * look.band * r);
    ctx.restore();
  }
  // shading: a highlight up-left, darker towards the rim (lightly, so the
  // stripes' white caps stay white)
  const shade = ctx.createRadialGradient(cx - 0.35 * r, cy - 0.4 * r, 0.05 * r, cx, cy, r);
  shade.addColorStop(0, 'rgba(255, 255, 255, 0.5)');
  shade.addColorStop(0.35, 'rgba(255, 255, 255, 0)');
  shade.addColorStop(1, 'rgba(0, 0, 0, 0.18)');
  ctx.fillStyle = shade;
  ctx.fill();
  ctx.lineWidth = 1;
  ctx.strokeStyle = 'rgba(0, 0, 0, 0.55)';
  ctx.stroke();

  if (style.label && r >= 4) {
    if (style.disc) {
      ctx.beginPath();
      ctx.arc(cx, cy, look.disc * r, 0, 2 * Math.PI);
      ctx.fillStyle = '#fbfaf5';
      ctx.fill();
    }
    ctx.fillStyle = '#111';
    const size = (style.label.length > 1 ? look.font2 : look.font1) * r;
    ctx.font = `700 ${Math.max(6, Math.round(size))}px system-ui, sans-serif`;
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    ctx.fillText(style.label, cx, cy + 0.06 * r, 1.9 * look.disc * r);
  }
  if (selected) {
    ctx.beginPath();
    ctx.arc(cx, cy, r + 4, 0, 2 * Math.PI);
    ctx.lineWidth = 2;
    ctx.strokeStyle = '#ffd84a';
    ctx.setLineDash([4, 3]);
    ctx.stroke();
  }
  ctx.restore();
}
