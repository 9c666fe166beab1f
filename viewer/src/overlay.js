// The aim overlay of a planned shot (`cueball plan-shot --html`, the
// result's optional "overlay"): the cue ball's aim line, a polyline from its
// centre at the strike to the ghost-ball position (through its cushion
// contacts on the way, for a kick), and the ghost ball, a dashed circle of
// the ball radius where the cue ball's centre is at first contact. Drawn on
// the cloth under the balls; a result without "overlay" draws nothing more.

/** Colour of the aim line and the ghost ball. */
export const OVERLAY_COLOUR = 'rgba(255, 255, 255, 0.85)';
/** Width of the aim line and the ghost ball's outline, CSS px. */
export const OVERLAY_WIDTH = 1.5;
/** Dash pattern (CSS px) of the ghost ball's outline; the aim line is solid. */
export const GHOST_DASH = [4, 3];

/**
 * The result's "overlay" checked: { aimLine: [[x, y], ...], ghostBall: [x, y] | null }
 * (metres), or null when the result has none. Throws naming the bad path.
 */
export function loadOverlay(result) {
  const o = result.overlay;
  if (o === undefined || o === null) return null;
  if (typeof o !== 'object' || Array.isArray(o)) throw new Error('overlay: expected an object');
  const point = (p, where) => {
    if (!Array.isArray(p) || p.length !== 2 || !p.every((v) => typeof v === 'number' && Number.isFinite(v))) {
      throw new Error(`overlay.${where}: expected [x, y], two finite numbers`);
    }
    return [p[0], p[1]];
  };
  if (!Array.isArray(o.aim_line) || o.aim_line.length < 2) {
    throw new Error('overlay.aim_line: expected at least two [x, y] points');
  }
  const aimLine = o.aim_line.map((p, i) => point(p, `aim_line[${i}]`));
  const ghostBall = o.ghost_ball === undefined || o.ghost_ball === null ? null : point(o.ghost_ball, 'ghost_ball');
  return { aimLine, ghostBall };
}

/**
 * Draws the overlay (ctx in table metres: view.applyTable). The ghost ball
 * has the radius `radius` (m).
 * @param {CanvasRenderingContext2D} ctx
 * @param {import('./geometry.js').View} view
 * @param {NonNullable<ReturnType<typeof loadOverlay>>} overlay
 */
export function drawOverlay(ctx, view, overlay, radius) {
  ctx.save();
  ctx.strokeStyle = OVERLAY_COLOUR;
  ctx.lineWidth = view.metres(OVERLAY_WIDTH);
  ctx.lineJoin = 'round';
  ctx.lineCap = 'round';
  ctx.setLineDash([]);
  ctx.beginPath();
  const [first, ...rest] = overlay.aimLine;
  ctx.moveTo(first[0], first[1]);
  for (const [x, y] of rest) ctx.lineTo(x, y);
  ctx.stroke();
  if (overlay.ghostBall) {
    const [x, y] = overlay.ghostBall;
    ctx.setLineDash(GHOST_DASH.map((d) => view.metres(d)));
    ctx.beginPath();
    ctx.arc(x, y, radius, 0, 2 * Math.PI);
    ctx.stroke();
  }
  ctx.restore();
}
