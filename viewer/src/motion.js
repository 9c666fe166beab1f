// Closed-form motion of one ball on the cloth: a port of src/cloth_motion.cpp
// (and include/cueball/cloth_motion.hpp, include/cueball/parameters.hpp).
// Equation numbers refer to paper 001 (A. Jaroukh, "Analysis of a billiard
// ball movement", 2019); the vertical spin follows spec §1.
//
// The page evaluates every ball from the result's trajectory segments with
// these formulas, so what it draws is the simulator's exact motion, not an
// interpolation of samples. The arithmetic follows the C++ operation by
// operation so both agree to rounding (test/motion.test.mjs checks ~1e-9 m
// against the C++ `samples`).
//
// A state is a plain object {x, y, vx, vy, wx, wy, wz}: centre position on
// the bed (m), velocity (m/s), angular velocity (rad/s, z up).

/** Slip speeds below this (m/s) count as zero: the ball is rolling. */
export const SLIP_TOLERANCE = 1e-12;
/** Speeds below this (m/s) count as zero: the ball is not translating. */
export const SPEED_TOLERANCE = 1e-12;
/** Vertical spins below this (rad/s) count as zero. */
export const SPIN_TOLERANCE = 1e-10;

export const Phase = Object.freeze({
  sliding: 'sliding',
  rolling: 'rolling',
  spinning: 'spinning',
  stationary: 'stationary',
});

export const Transition = Object.freeze({
  none: 'none',
  slidingEnds: 'sliding_ends',
  rollingEnds: 'rolling_ends',
  verticalSpinEnds: 'vertical_spin_ends',
});

/**
 * Cloth parameters from the result's `parameters` object.
 * @param {{radius:number, mu_s:number, mu_r:number, mu_sp:number, g:number}} p
 */
export function clothParameters(p) {
  return {
    radius: p.radius,
    // mu_s g (paper 001 eq. 2)
    slidingDeceleration: p.mu_s * p.g,
    // (5/7) mu_r g (paper 001, from eqs 11-12)
    rollingDeceleration: (5.0 / 7.0) * p.mu_r * p.g,
    // 5 mu_sp g / (2R), rad/s^2
    spinDeceleration: (2.5 * p.mu_sp * p.g) / p.radius,
  };
}

export function makeState(position, velocity, angularVelocity) {
  return {
    x: position[0],
    y: position[1],
    vx: velocity[0],
    vy: velocity[1],
    wx: angularVelocity[0],
    wy: angularVelocity[1],
    wz: angularVelocity[2],
  };
}

/** Contact-point slip velocity u = v + R z^ x w (paper 001 eq. 1), as [ux, uy]. */
export function slipVelocity(s, radius) {
  return [s.vx - radius * s.wy, s.vy + radius * s.wx];
}

export function speed(s) {
  return Math.sqrt(s.vx * s.vx + s.vy * s.vy);
}

export function angularSpeed(s) {
  return Math.sqrt(s.wx * s.wx + s.wy * s.wy + s.wz * s.wz);
}

/** The motion phase, derived from the kinematics (never from a stored label). */
export function motionPhase(s, cp) {
  const [ux, uy] = slipVelocity(s, cp.radius);
  if (ux * ux + uy * uy > SLIP_TOLERANCE * SLIP_TOLERANCE) return Phase.sliding;
  if (s.vx * s.vx + s.vy * s.vy > SPEED_TOLERANCE * SPEED_TOLERANCE) return Phase.rolling;
  if (Math.abs(s.wz) > SPIN_TOLERANCE) return Phase.spinning;
  return Phase.stationary;
}

// Time for the vertical spin to decay to zero; +Infinity when there is none.
function verticalSpinStopTime(wz, cp) {
  return Math.abs(wz) > SPIN_TOLERANCE ? Math.abs(wz) / cp.spinDeceleration : Infinity;
}

// w_z after dt: linear decay towards zero, clamped (it never reverses).
function decayVerticalSpin(wz, dt, cp) {
  if (dt >= verticalSpinStopTime(wz, cp) || Math.abs(wz) <= SPIN_TOLERANCE) return 0.0;
  return wz - Math.sign(wz) * (cp.spinDeceleration * dt);
}

// Duration of sliding, t1 = 2|u0| / (7 mu_s g) (eq. 8).
function slidingTime(slipSpeed, cp) {
  return (2.0 * slipSpeed) / (7.0 * cp.slidingDeceleration);
}

// Duration of rolling until rest, 7|v1| / (5 mu_r g) (eq. 22 with v2 = 0).
function rollingTime(v, cp) {
  return v / cp.rollingDeceleration;
}

function slide(s, dt, cp) {
  const radius = cp.radius;
  const [u0x, u0y] = slipVelocity(s, radius);
  const slipSpeed = Math.sqrt(u0x * u0x + u0y * u0y);
  const uhx = u0x / slipSpeed; // u^ is constant while sliding (eq. 4)
  const uhy = u0y / slipSpeed;
  const a = cp.slidingDeceleration;
  const t1 = slidingTime(slipSpeed, cp);
  const t = dt < t1 ? dt : t1;

  const half = 0.5 * a * t * t;
  const out = {
    x: s.x + t * s.vx - half * uhx, // eq. 7
    y: s.y + t * s.vy - half * uhy,
    vx: s.vx - a * t * uhx, // eq. 6
    vy: s.vy - a * t * uhy,
    wx: 0,
    wy: 0,
    wz: decayVerticalSpin(s.wz, dt, cp),
  };
  if (t < t1) {
    // w = w0 + (5 mu_s g / 2R) t (z^ x u^)  (eq. 3 integrated); z^ x u^ = perp(u^) = (-u^y, u^x)
    const k = (2.5 * a * t) / radius;
    out.wx = s.wx + k * -uhy;
    out.wy = s.wy + k * uhx;
  } else {
    // End of sliding: v1 = v0 - 2/7 u0 (eq. 9). Snap exactly onto rolling.
    out.vx = s.vx - (2.0 / 7.0) * u0x;
    out.vy = s.vy - (2.0 / 7.0) * u0y;
    if (speed(out) <= SPEED_TOLERANCE) {
      out.vx = 0; // a perfect stop shot
      out.vy = 0;
    }
    setRollingSpin(out, radius);
  }
  return out;
}

// Horizontal angular velocity of a ball rolling without slip: u = 0 in eq. 1
// gives w_h = z^ x v / R = perp(v) / R.
function setRollingSpin(s, radius) {
  s.wx = -s.vy / radius;
  s.wy = s.vx / radius;
}

function roll(s, dt, cp) {
  const v = speed(s);
  const vhx = s.vx / v;
  const vhy = s.vy / v;
  const a = cp.rollingDeceleration;
  const out = { x: 0, y: 0, vx: 0, vy: 0, wx: 0, wy: 0, wz: decayVerticalSpin(s.wz, dt, cp) };
  if (dt < rollingTime(v, cp)) {
    const half = 0.5 * a * dt * dt;
    out.x = s.x + dt * s.vx - half * vhx; // eq. 14
    out.y = s.y + dt * s.vy - half * vhy;
    out.vx = s.vx - a * dt * vhx; // eq. 13
    out.vy = s.vy - a * dt * vhy;
    setRollingSpin(out, cp.radius);
  } else {
    // eq. 14 at the stop: |v|^2 / 2a along v^
    const k = (0.5 * v) / a;
    out.x = s.x + k * s.vx;
    out.y = s.y + k * s.vy;
  }
  return out;
}

/**
 * Time until the equations of motion next change, and what changes.
 * @returns {{time:number, kind:string}}
 */
export function nextTransition(s, cp) {
  const tSpin = verticalSpinStopTime(s.wz, cp);
  let tPhase = Infinity;
  let phaseEnd = Transition.none;
  switch (motionPhase(s, cp)) {
    case Phase.sliding: {
      const [ux, uy] = slipVelocity(s, cp.radius);
      tPhase = slidingTime(Math.sqrt(ux * ux + uy * uy), cp);
      phaseEnd = Transition.slidingEnds;
      break;
    }
    case Phase.rolling:
      tPhase = rollingTime(speed(s), cp);
      phaseEnd = Transition.rollingEnds;
      break;
    default:
      break;
  }
  if (tSpin < tPhase) return { time: tSpin, kind: Transition.verticalSpinEnds };
  return { time: tPhase, kind: phaseEnd };
}

/**
 * The state after dt seconds, assuming the ball stays in `phase` for the whole
 * interval (0 <= dt <= the next transition's time); snapped onto the new phase
 * at the transition.
 */
export function evolveInPhase(s, phase, dt, cp) {
  switch (phase) {
    case Phase.sliding:
      return slide(s, dt, cp);
    case Phase.rolling:
      return roll(s, dt, cp);
    case Phase.spinning:
      return { x: s.x, y: s.y, vx: 0, vy: 0, wx: 0, wy: 0, wz: decayVerticalSpin(s.wz, dt, cp) };
    default:
      return { x: s.x, y: s.y, vx: 0, vy: 0, wx: 0, wy: 0, wz: 0 };
  }
}

/**
 * The state after dt >= 0 seconds, crossing as many phase transitions as
 * needed (C++ `evolve`).
 */
export function evolve(s, dt, cp) {
  let state = s;
  // Each pass either finishes or crosses one transition; there are at most
  // four (sliding ends, rolling ends, vertical spin ends, and nothing moves).
  for (let pass = 0; pass < 5; ++pass) {
    const phase = motionPhase(state, cp);
    const next = nextTransition(state, cp);
    if (dt < next.time || next.kind === Transition.none) return evolveInPhase(state, phase, dt, cp);
    state = evolveInPhase(state, phase, next.time, cp);
    dt -= next.time;
  }
  return state;
}

/**
 * The closed-form pieces of motion starting from `s` over [0, duration]: one
 * entry per phase with its start and end times (relative to s), for trails
 * and plots. Each piece carries the state at its start.
 * @returns {{t0:number, t1:number, phase:string, state:object}[]}
 */
export function phasePieces(s, duration, cp) {
  const pieces = [];
  let state = s;
  let t = 0;
  for (let pass = 0; pass < 6 && t < duration; ++pass) {
    const phase = motionPhase(state, cp);
    const next = nextTransition(state, cp);
    const end = next.kind === Transition.none ? duration : Math.min(duration, t + next.time);
    pieces.push({ t0: t, t1: end, phase, state });
    if (end >= duration) break;
    state = evolveInPhase(state, phase, next.time, cp);
    t = end;
  }
  return pieces;
}
