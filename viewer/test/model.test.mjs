// The model and geometry the page draws from: trails, plot series, pockets,
// the cushion outline, names of balls, cushions and events.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { ballStyle } from '../src/balls.js';
import { describeEvent, describeGeometry } from '../src/format.js';
import { noseOutline, tableLayout, View } from '../src/geometry.js';
import { loadResult, pathPieces, phaseAt, speedSeries, stateAt } from '../src/model.js';
import { angularSpeed, speed } from '../src/motion.js';
import { niceCeiling } from '../src/plot.js';
import { FIXTURE_NAMES, readFixture } from './helpers.mjs';

const models = Object.fromEntries(FIXTURE_NAMES.map((n) => [n, loadResult(readFixture(n))]));

describe('trails', () => {
  test('trail pieces lie on the exact path and alternate sliding/rolling', () => {
    for (const model of Object.values(models)) {
      for (const ball of model.balls) {
        const pieces = pathPieces(model, ball);
        for (const piece of pieces) {
          assert.ok(piece.phase === 'sliding' || piece.phase === 'rolling');
          assert.ok(piece.t1 > piece.t0);
          const p = piece.points;
          assert.equal(p[0], piece.t0);
          assert.equal(p[p.length - 3], piece.t1);
          for (let i = 0; i < p.length; i += 3) {
            const s = stateAt(model, ball, p[i]);
            assert.ok(Math.hypot(s.x - p[i + 1], s.y - p[i + 2]) < 1e-9, `${ball.name} trail point at ${p[i]}`);
          }
        }
        // a moving ball has a trail; the whole trail ends before its pocket time
        if (ball.segments.some((s) => s.phase === 'sliding' || s.phase === 'rolling')) assert.ok(pieces.length > 0);
        for (const piece of pieces) assert.ok(piece.t1 <= ball.pocketTime);
      }
    }
  });

  test('the cue ball of the break slides first, then rolls', () => {
    const model = models['nine-ball-break'];
    const pieces = pathPieces(model, model.byId.get(0));
    assert.equal(pieces[0].phase, 'sliding');
    assert.equal(pieces[0].t0, 0);
    assert.ok(pieces.some((p) => p.phase === 'rolling'));
  });
});

describe('pockets', () => {
  const model = models['cut-shot'];
  const one = model.balls.find((b) => b.name === '1');

  test('a pocketed ball stays where it was captured, in its pocket', () => {
    assert.ok(one.pocketed);
    assert.equal(one.pocketName, 'top-right');
    assert.equal(one.pocket.name, 'top-right');
    assert.equal(phaseAt(model, one, one.pocketTime), 'pocketed');
    assert.notEqual(phaseAt(model, one, one.pocketTime - 1e-6), 'pocketed');
    const s = stateAt(model, one, one.pocketTime + 1);
    assert.deepEqual([s.x, s.y], [one.finalState.x, one.finalState.y]);
    const d = Math.hypot(s.x - one.pocket.centre[0], s.y - one.pocket.centre[1]);
    assert.ok(d <= one.pocket.radius + 1e-9, 'captured inside the pocket circle');
  });

  test("the plot series stops at the pocket time", () => {
    const series = speedSeries(model, one);
    assert.ok(series.t[series.t.length - 1] <= one.pocketTime);
    assert.ok(series.v.some((v) => v > 1), 'the 1 ball moved');
  });
});

describe('plot series', () => {
  test('are exact |v| and |w| in time order, over the whole shot', () => {
    for (const model of Object.values(models)) {
      for (const ball of model.balls) {
        const { t, v, w } = speedSeries(model, ball, 200);
        assert.equal(t.length, v.length);
        assert.equal(t.length, w.length);
        for (let i = 1; i < t.length; ++i) assert.ok(t[i] >= t[i - 1]);
        if (!ball.pocketed) assert.equal(t[t.length - 1], model.duration);
        const k = Math.floor(t.length / 2);
        if (t[k] !== t[k - 1] && t[k] !== t[k + 1]) {
          const s = stateAt(model, ball, t[k]);
          assert.equal(v[k], speed(s));
          assert.equal(w[k], angularSpeed(s));
        }
      }
    }
  });

  test('include the speed just before and just after each collision', () => {
    const model = models['nine-ball-break'];
    const cue = model.byId.get(0);
    const { t, v } = speedSeries(model, cue);
    const hit = cue.segments[1].t; // the cue ball hits the 1
    const at = t.map((x, i) => [x, v[i]]).filter(([x]) => x === hit);
    assert.ok(at.length >= 2);
    assert.ok(at[0][1] > 5 && at[at.length - 1][1] < 1, `${at.map((a) => a[1])}`);
  });

  test('axis maxima are 1, 2, 2.5 or 5 times a power of ten', () => {
    assert.equal(niceCeiling(9.3), 10);
    assert.equal(niceCeiling(0.7), 1);
    assert.equal(niceCeiling(21), 25);
    assert.equal(niceCeiling(130), 200);
    assert.equal(niceCeiling(0), 1);
  });
});

describe('table geometry', () => {
  test('the nose outline joins every cushion through its jaw, or across a pocket mouth', () => {
    for (const [name, model] of Object.entries(models)) {
      const { table } = model;
      const outline = noseOutline(table);
      const arcs = outline.filter((p) => p.kind === 'arc');
      assert.equal(arcs.length, table.jaws.length, `${name}: one arc per jaw`);
      for (const arc of arcs) assert.ok(Math.abs(arc.a1 - arc.a0) < Math.PI);
      const mouths = outline.filter((p) => p.kind === 'line').length - table.cushions.length;
      assert.equal(mouths, table.pockets.length, `${name}: one mouth per pocket`);
    }
  });

  test('the rail is drawn outside the cushions, pockets and diamonds', () => {
    for (const model of Object.values(models)) {
      const { table } = model;
      const layout = tableLayout(table, model.radius);
      assert.ok(layout.cushionBack > 0 && layout.railOuter > layout.cushionBack);
      const inside = ([x, y], margin) =>
        x >= -margin && y >= -margin && x <= table.length + margin && y <= table.width + margin;
      for (const d of table.diamonds) assert.ok(inside(d, layout.railOuter) && !inside(d, layout.cushionBack));
      for (const c of table.cushions) assert.ok(inside(c.start, layout.cushionBack + 1e-12));
    }
  });

  test('the view fits the table, keeps its aspect and flips y', () => {
    const layout = tableLayout(models['nine-ball-break'].table, 0.028575);
    const view = new View(layout.extent, 1000, 400, 2);
    const [x0, y0] = view.toCss(layout.extent.x0, layout.extent.y0);
    const [x1, y1] = view.toCss(layout.extent.x1, layout.extent.y1);
    assert.ok(x0 >= 0 && x1 <= 1000 && y1 >= 0 && y0 <= 400);
    assert.ok(y1 < y0, 'y up');
    assert.ok(Math.abs(x1 - x0 - (layout.extent.x1 - layout.extent.x0) * view.scale) < 1e-9);
    assert.ok(Math.abs(400 - 2 * 8 - (y0 - y1)) < 1e-9, 'fills the height');
    const back = view.toTable(...view.toCss(1.2, 0.3));
    assert.ok(Math.abs(back[0] - 1.2) < 1e-12 && Math.abs(back[1] - 0.3) < 1e-12);
  });

  test('cushions and jaws are named by rail and pocket', () => {
    const names = describeGeometry(models['nine-ball-break'].table);
    assert.deepEqual(names.cushions.slice(0, 3), ['bottom-left facing', 'bottom-left facing', 'bottom-left cushion']);
    assert.equal(names.cushions[8], 'right cushion');
    assert.equal(names.jaws[0], 'bottom-left jaw');
    const carom = describeGeometry(models['carom-side-spin'].table);
    assert.deepEqual(new Set(carom.cushions), new Set(['bottom cushion', 'right cushion', 'top cushion', 'left cushion']));
  });
});

describe('names', () => {
  test('events read as sentences', () => {
    const model = models['cut-shot'];
    const names = describeGeometry(model.table);
    const text = model.events.map((e) => describeEvent(e, model, names));
    assert.equal(text[0], 'cue struck');
    assert.equal(text[1], 'cue × 1');
    assert.ok(text.includes('1 pocketed (top-right)'));
    assert.ok(text.includes('cue hits the right cushion'));
    assert.ok(text.includes('cue: slide → roll'));
  });

  test('balls get pool, snooker and carom colours; others a neutral colour and their name', () => {
    assert.deepEqual(ballStyle('1'), { colour: '#f4c20d', stripe: false, label: '1', disc: true });
    assert.equal(ballStyle('9').stripe, true);
    assert.equal(ballStyle('9').colour, ballStyle('1').colour);
    assert.equal(ballStyle('red7').colour, ballStyle('red').colour);
    assert.equal(ballStyle('cue').colour, ballStyle('white').colour);
    assert.equal(ballStyle('pink').label, '');
    assert.equal(ballStyle('ghost').label, 'gho');
    assert.equal(ballStyle('42').label, '42');
  });
});
