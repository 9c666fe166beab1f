// Ball trails: the path travelled up to the current time, drawn solid where
// the ball was rolling and dashed where it was sliding (slip u != 0).

import { Phase } from './motion.js';

/** Dash pattern (CSS px) of sliding trails; rolling trails are solid. */
export const SLIDING_DASH = [5, 4];

/**
 * Draws one ball's trail from t = 0 to `time` (context in table metres).
 * @param {{phase:string, t0:number, t1:number, points:number[]}[]} pieces from pathPieces()
 * @param {number[]} now the ball's position [x, y] at `time`
 */
export function drawTrail(ctx, view, pieces, time, now, colour, { width = 1.6, alpha = 0.8 } = {}) {
  ctx.save();
  ctx.globalAlpha = alpha;
  ctx.strokeStyle = colour;
  ctx.lineWidth = view.metres(width);
  ctx.lineJoin = 'round';
  for (const phase of [Phase.rolling, Phase.sliding]) {
    ctx.setLineDash(phase === Phase.sliding ? SLIDING_DASH.map((d) => view.metres(d)) : []);
    ctx.beginPath();
    for (const piece of pieces) {
      if (piece.phase !== phase || piece.t0 >= time) continue;
      const p = piece.points;
      ctx.moveTo(p[1], p[2]);
      let i = 3;
      for (; i < p.length && p[i] <= time; i += 3) ctx.lineTo(p[i + 1], p[i + 2]);
      if (i < p.length) ctx.lineTo(now[0], now[1]); // the piece is under way
    }
    ctx.stroke();
  }
  ctx.restore();
}
