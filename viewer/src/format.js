// Text for times, quantities and events.

/** "1.234 s" */
export function formatTime(t) {
  return `${t.toFixed(3)} s`;
}

/** Short human names of the event types (src/simulator.cpp to_string(EventType)). */
export const EVENT_LABELS = {
  cue_strike: 'cue strike',
  ball_ball: 'ball–ball',
  ball_cushion: 'cushion',
  ball_jaw: 'jaw',
  ball_pocket: 'pocket',
  slide_to_roll: 'slide → roll',
  roll_to_spin: 'roll → spin',
  roll_to_rest: 'roll → rest',
  spin_stop: 'spin stops',
};

/**
 * Names of the cushions for event descriptions: the long straight noses by
 * the rail they are on ("bottom", "top-left"...), the short facings and the
 * jaws by their nearest pocket.
 */
export function describeGeometry(table) {
  const { length: L, width: W } = table;
  const pockets = table.pockets || [];
  const nearestPocket = (p) => {
    let best = null;
    let bestD = Infinity;
    for (const q of pockets) {
      const d = Math.hypot(p[0] - q.centre[0], p[1] - q.centre[1]);
      if (d < bestD) [best, bestD] = [q.name, d];
    }
    return best;
  };
  const eps = 1e-6;
  const cushions = (table.cushions || []).map((c) => {
    const mid = [(c.start[0] + c.end[0]) / 2, (c.start[1] + c.end[1]) / 2];
    let rail = null;
    if (Math.abs(c.start[1] - c.end[1]) < eps && Math.abs(mid[1]) < eps) rail = 'bottom';
    else if (Math.abs(c.start[1] - c.end[1]) < eps && Math.abs(mid[1] - W) < eps) rail = 'top';
    else if (Math.abs(c.start[0] - c.end[0]) < eps && Math.abs(mid[0]) < eps) rail = 'left';
    else if (Math.abs(c.start[0] - c.end[0]) < eps && Math.abs(mid[0] - L) < eps) rail = 'right';
    if (rail === 'bottom' || rail === 'top') {
      // long rails split by a side pocket: name the half
      const split = pockets.some((p) => p.centre[0] > 0.25 * L && p.centre[0] < 0.75 * L);
      return split ? `${rail}-${mid[0] < L / 2 ? 'left' : 'right'} cushion` : `${rail} cushion`;
    }
    if (rail) return `${rail} cushion`;
    const pocket = nearestPocket(mid);
    return pocket ? `${pocket} facing` : 'cushion';
  });
  const jaws = (table.jaws || []).map((j) => {
    const pocket = nearestPocket(j.centre);
    return pocket ? `${pocket} jaw` : 'jaw';
  });
  return { cushions, jaws };
}

/** One line describing an event, e.g. "cue × 1" or "4 hits the top-right cushion". */
export function describeEvent(event, model, names) {
  const ballName = (id) => {
    const b = model.byId.get(id);
    return b ? b.name : String(id);
  };
  const who = event.balls.map(ballName).join(' × ');
  switch (event.type) {
    case 'cue_strike':
      return `${who} struck`;
    case 'ball_ball':
      return who;
    case 'ball_cushion':
      return `${who} hits the ${names.cushions[event.cushion] || `cushion ${event.cushion}`}`;
    case 'ball_jaw':
      return `${who} hits the ${names.jaws[event.jaw] || `jaw ${event.jaw}`}`;
    case 'ball_pocket':
      return `${who} pocketed (${event.pocket})`;
    default:
      return `${who}: ${EVENT_LABELS[event.type] || event.type}`;
  }
}
