// The simulation result (`cueball simulate -o r.json`) as the viewer uses it:
// balls with their trajectory segments, events, table and parameters, and the
// state of any ball at any time (C++ SimulationResult::state_at).

import { loadOverlay } from './overlay.js';
import { angularSpeed, clothParameters, evolve, makeState, motionPhase, phasePieces, Phase, speed } from './motion.js';

/** Seconds a pocketed ball takes to disappear into its pocket on screen. */
export const POCKET_DROP_TIME = 0.25;

/** Event types that are transitions of the motion, not contacts. */
export const TRANSITION_EVENTS = new Set(['slide_to_roll', 'roll_to_spin', 'roll_to_rest', 'spin_stop']);

/**
 * Builds the viewer's model from the parsed result JSON.
 * @param {any} result
 */
export function loadResult(result) {
  if (!result || typeof result !== 'object') throw new Error('the result is not a JSON object');
  for (const key of ['table', 'parameters', 'balls', 'events', 'end_time']) {
    if (!(key in result)) throw new Error(`the result has no "${key}"`);
  }
  const cloth = clothParameters(result.parameters);
  const pockets = new Map((result.table.pockets || []).map((p) => [p.name, p]));
  const balls = result.balls.map((b, index) => {
    const segments = b.segments.map((s) => ({
      t: s.t,
      phase: s.phase,
      state: makeState(s.position, s.velocity, s.angular_velocity),
    }));
    if (segments.length === 0) throw new Error(`ball ${b.id} has no trajectory segments`);
    return {
      index,
      id: b.id,
      name: String(b.name),
      pocketed: Boolean(b.pocketed),
      pocket: b.pocketed ? pockets.get(b.pocket) || null : null,
      pocketName: b.pocketed ? b.pocket : null,
      pocketTime: b.pocketed ? b.pocket_time : Infinity,
      finalState: makeState(b.position, b.velocity, b.angular_velocity),
      segments,
    };
  });
  const byId = new Map(balls.map((b) => [b.id, b]));
  const events = result.events.map((e, index) => ({
    index,
    time: e.time,
    type: e.type,
    balls: e.balls || [],
    cushion: e.cushion,
    jaw: e.jaw,
    pocket: e.pocket,
  }));
  return {
    table: result.table,
    parameters: result.parameters,
    cloth,
    radius: result.parameters.radius,
    duration: result.end_time,
    balls,
    byId,
    events,
    overlay: loadOverlay(result),
  };
}

// Index of the last segment with t <= time (the first one if none).
function segmentIndex(segments, time) {
  let lo = 0;
  let hi = segments.length; // first index with segments[i].t > time
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (time < segments[mid].t) hi = mid;
    else lo = mid + 1;
  }
  return lo === 0 ? 0 : lo - 1;
}

/**
 * Kinematic state of a ball at time t (s): the last segment starting at or
 * before t, evolved in closed form. A pocketed ball keeps its final state
 * (where it was captured) from its pocket time on.
 */
export function stateAt(model, ball, t) {
  if (ball.pocketed && t >= ball.pocketTime) return ball.finalState;
  const seg = ball.segments[segmentIndex(ball.segments, t)];
  return evolve(seg.state, Math.max(0, t - seg.t), model.cloth);
}

/** "sliding", "rolling", "spinning", "stationary" or "pocketed". */
export function phaseAt(model, ball, t) {
  if (ball.pocketed && t >= ball.pocketTime) return 'pocketed';
  return motionPhase(stateAt(model, ball, t), model.cloth);
}

/** End of the interval covered by segment k of a ball. */
function segmentEnd(model, ball, k) {
  if (k + 1 < ball.segments.length) return ball.segments[k + 1].t;
  return Math.min(ball.pocketTime, model.duration);
}

/**
 * The ball's path as closed-form pieces in absolute time, each sliding or
 * rolling (the phases where it moves), sampled into polylines for drawing:
 * rolling pieces are straight, sliding pieces are parabolas (eq. 7).
 * @returns {{phase:string, t0:number, t1:number, points:number[]}[]} points are [t, x, y, ...]
 */
export function pathPieces(model, ball) {
  const out = [];
  ball.segments.forEach((seg, k) => {
    const end = Math.min(segmentEnd(model, ball, k), ball.pocketTime);
    if (!(end > seg.t)) return;
    for (const piece of phasePieces(seg.state, end - seg.t, model.cloth)) {
      if (piece.phase !== Phase.sliding && piece.phase !== Phase.rolling) continue;
      const t0 = seg.t + piece.t0;
      const t1 = seg.t + piece.t1;
      if (!(t1 > t0)) continue;
      const dt = piece.t1 - piece.t0;
      const n = piece.phase === Phase.rolling ? 1 : Math.min(120, Math.max(4, Math.ceil(dt / 0.004)));
      const points = [];
      for (let i = 0; i <= n; ++i) {
        const tau = (dt * i) / n;
        const s = evolve(piece.state, tau, model.cloth);
        points.push(i === n ? t1 : t0 + tau, s.x, s.y);
      }
      out.push({ phase: piece.phase, t0, t1, points });
    }
  });
  return out;
}

/**
 * |v| (m/s) and |w| (rad/s) of a ball over [0, duration] for the plots:
 * sampled on a uniform grid, at every phase transition, and on both sides of
 * every segment start (where a collision changes them abruptly). A pocketed
 * ball drops to zero at its pocket time and the series ends there.
 * @returns {{t:number[], v:number[], w:number[]}}
 */
export function speedSeries(model, ball, gridPoints = 600) {
  const { duration, cloth } = model;
  const items = []; // {t, state}: state given for "just before" a segment start
  const add = (t, state = null) => items.push({ t, state });
  for (let i = 0; i <= gridPoints; ++i) add((duration * i) / gridPoints);
  ball.segments.forEach((seg, k) => {
    const end = Math.min(segmentEnd(model, ball, k), duration);
    for (const piece of phasePieces(seg.state, Math.max(0, end - seg.t), cloth)) add(seg.t + piece.t1);
    add(seg.t);
    if (k > 0) {
      const prev = ball.segments[k - 1];
      add(seg.t, evolve(prev.state, seg.t - prev.t, cloth));
    }
  });
  if (ball.pocketed) {
    const last = ball.segments[segmentIndex(ball.segments, ball.pocketTime)];
    add(ball.pocketTime, evolve(last.state, ball.pocketTime - last.t, cloth)); // at capture
  }
  // by time; at equal times the states "just before" first
  items.sort((a, b) => a.t - b.t || (b.state ? 1 : 0) - (a.state ? 1 : 0));
  const series = { t: [], v: [], w: [] };
  for (const { t, state } of items) {
    if (!(t >= 0 && t <= duration) || t > ball.pocketTime) continue;
    const s = state || stateAt(model, ball, t);
    series.t.push(t);
    series.v.push(speed(s));
    series.w.push(angularSpeed(s));
  }
  return series;
}
