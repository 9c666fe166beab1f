// The page's closed-form evaluation (src/motion.js, src/model.js) against the
// C++ simulator: every sampled state in the fixtures (cueball simulate
// --sample, i.e. C++ SimulationResult::state_at) must agree to ~1e-9.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { loadResult, stateAt } from '../src/model.js';
import { clothParameters, evolve, makeState, motionPhase, nextTransition, Phase } from '../src/motion.js';
import { FIXTURE_NAMES, readFixture } from './helpers.mjs';

const POSITION_TOLERANCE = 1e-9; // m
const VELOCITY_TOLERANCE = 1e-9; // m/s
const SPIN_TOLERANCE = 1e-7; // rad/s (|w| ~ v / R, about 35 times |v|)

function assertClose(actual, expected, tolerance, what) {
  const error = Math.abs(actual - expected);
  assert.ok(error <= tolerance, `${what}: ${actual} vs C++ ${expected} (error ${error.toExponential(2)})`);
}

for (const name of FIXTURE_NAMES) {
  describe(`fixture ${name}`, () => {
    const result = readFixture(name);
    const model = loadResult(result);

    test('every sample matches the C++ state', () => {
      const { times, balls } = result.samples;
      let checked = 0;
      let worst = 0;
      for (const sampled of balls) {
        const ball = model.byId.get(sampled.id);
        assert.ok(ball, `ball ${sampled.id} is in the model`);
        times.forEach((t, k) => {
          const s = stateAt(model, ball, t);
          const what = (q) => `${name}: ball ${ball.name} ${q} at t = ${t}`;
          const [x, y] = sampled.position[k];
          const [vx, vy] = sampled.velocity[k];
          const [wx, wy, wz] = sampled.angular_velocity[k];
          assertClose(s.x, x, POSITION_TOLERANCE, what('x'));
          assertClose(s.y, y, POSITION_TOLERANCE, what('y'));
          assertClose(s.vx, vx, VELOCITY_TOLERANCE, what('vx'));
          assertClose(s.vy, vy, VELOCITY_TOLERANCE, what('vy'));
          assertClose(s.wx, wx, SPIN_TOLERANCE, what('wx'));
          assertClose(s.wy, wy, SPIN_TOLERANCE, what('wy'));
          assertClose(s.wz, wz, SPIN_TOLERANCE, what('wz'));
          worst = Math.max(worst, Math.abs(s.x - x), Math.abs(s.y - y));
          checked += 1;
        });
      }
      assert.ok(checked > 100, `${checked} samples checked`);
      assert.ok(worst <= POSITION_TOLERANCE);
    });

    test('each segment, evolved to the next one, ends where the C++ put it', () => {
      // Segments start at collisions, computed by C++ evolve(); positions are
      // continuous through a collision.
      for (const ball of model.balls) {
        for (let k = 1; k < ball.segments.length; ++k) {
          const prev = ball.segments[k - 1];
          const next = ball.segments[k];
          const s = evolve(prev.state, next.t - prev.t, model.cloth);
          assertClose(s.x, next.state.x, POSITION_TOLERANCE, `${name}: ball ${ball.name} segment ${k} x`);
          assertClose(s.y, next.state.y, POSITION_TOLERANCE, `${name}: ball ${ball.name} segment ${k} y`);
        }
      }
    });

    test('the phase of each segment is the one the C++ reports', () => {
      for (const ball of model.balls) {
        for (const seg of ball.segments) assert.equal(motionPhase(seg.state, model.cloth), seg.phase);
      }
    });

    test('the final state is where every ball ends', () => {
      for (const ball of model.balls) {
        const s = stateAt(model, ball, model.duration);
        assertClose(s.x, ball.finalState.x, POSITION_TOLERANCE, `${name}: ball ${ball.name} final x`);
        assertClose(s.y, ball.finalState.y, POSITION_TOLERANCE, `${name}: ball ${ball.name} final y`);
        if (!ball.pocketed) assert.equal(motionPhase(s, model.cloth), Phase.stationary);
      }
    });
  });
}

describe('closed forms (paper 001)', () => {
  const cp = clothParameters({ radius: 0.028575, mu_s: 0.2, mu_r: 0.014, mu_sp: 0.0117, g: 9.81 });

  test('a stun shot slides for t1 = 2|u0| / (7 mu_s g), then rolls at v1 = 5/7 v0 (eqs 8, 9)', () => {
    const v0 = 2;
    const s0 = makeState([0, 0], [v0, 0], [0, 0, 0]);
    const next = nextTransition(s0, cp);
    assert.equal(next.kind, 'sliding_ends');
    assertClose(next.time, (2 * v0) / (7 * 0.2 * 9.81), 1e-15, 't1');
    const s1 = evolve(s0, next.time, cp);
    assert.equal(motionPhase(s1, cp), Phase.rolling);
    assertClose(s1.vx, (5 / 7) * v0, 1e-15, 'v1');
    assertClose(s1.wy, s1.vx / cp.radius, 1e-12, 'rolling spin');
  });

  test('a rolling ball stops after |v| / a_r at |v|^2 / 2 a_r (eqs 13, 14)', () => {
    const s0 = makeState([1, 1], [0, 0.5], [-0.5 / cp.radius, 0, 0]);
    assert.equal(motionPhase(s0, cp), Phase.rolling);
    const a = (5 / 7) * 0.014 * 9.81;
    const rest = evolve(s0, 100, cp);
    assertClose(rest.y, 1 + (0.5 * 0.5) / (2 * a), 1e-12, 'rest position');
    assert.equal(motionPhase(rest, cp), Phase.stationary);
    const half = evolve(s0, 0.5 / a / 2, cp);
    assertClose(half.vy, 0.25, 1e-12, 'speed halfway');
  });

  test('vertical spin decays linearly and never reverses', () => {
    const s0 = makeState([0, 0], [0, 0], [0, 0, -10]);
    assert.equal(motionPhase(s0, cp), Phase.spinning);
    const rate = (2.5 * 0.0117 * 9.81) / 0.028575;
    assertClose(evolve(s0, 0.5, cp).wz, -10 + 0.5 * rate, 1e-12, 'w_z after 0.5 s');
    assert.equal(evolve(s0, 1000, cp).wz, 0);
  });

  test('a draw shot reverses: sliding decelerates it through zero', () => {
    const s0 = makeState([0, 0], [1, 0], [0, -4 / cp.radius, 0]); // strong backspin: u0 = 5 m/s
    const s1 = evolve(s0, nextTransition(s0, cp).time, cp);
    assert.ok(s1.vx < 0, 'comes back');
    assertClose(s1.vx, 1 - (2 / 7) * 5, 1e-12, 'v1 = v0 - 2/7 u0');
    assert.equal(motionPhase(s1, cp), Phase.rolling);
  });
});
