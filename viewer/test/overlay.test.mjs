// The aim overlay (src/overlay.js): the result's "overlay" read and checked,
// drawn as a solid aim line through its points and a dashed ghost-ball
// circle of the ball radius; a result without it has none.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { View, tableLayout } from '../src/geometry.js';
import { loadResult } from '../src/model.js';
import { drawOverlay, GHOST_DASH, loadOverlay, OVERLAY_WIDTH } from '../src/overlay.js';
import { readFixture } from './helpers.mjs';

const withOverlay = (overlay) => ({ ...readFixture('cut-shot'), overlay });

// A 2D context that records the calls and the dash pattern of each stroke.
function recordingContext() {
  const calls = [];
  let dash = [];
  return {
    calls,
    save() {},
    restore() {},
    setLineDash(d) {
      dash = d;
    },
    beginPath() {
      calls.push(['beginPath']);
    },
    moveTo(x, y) {
      calls.push(['moveTo', x, y]);
    },
    lineTo(x, y) {
      calls.push(['lineTo', x, y]);
    },
    arc(x, y, r, a0, a1) {
      calls.push(['arc', x, y, r, a0, a1]);
    },
    stroke() {
      calls.push(['stroke', [...dash], this.lineWidth]);
    },
  };
}

describe('overlay', () => {
  test('a result without "overlay" (every fixture) has none', () => {
    for (const name of ['nine-ball-break', 'cut-shot', 'snooker-break', 'carom-side-spin']) {
      assert.equal(loadResult(readFixture(name)).overlay, null, name);
    }
    assert.equal(loadOverlay({ overlay: null }), null);
  });

  test('is read as given: the aim line a polyline, the ghost ball a point or null', () => {
    const model = loadResult(withOverlay({ aim_line: [[0.5, 0.5], [2.5, 0.1], [1.7, 0.9]], ghost_ball: [1.7, 0.9] }));
    assert.deepEqual(model.overlay, { aimLine: [[0.5, 0.5], [2.5, 0.1], [1.7, 0.9]], ghostBall: [1.7, 0.9] });
    assert.equal(loadOverlay({ overlay: { aim_line: [[0, 0], [1, 1]], ghost_ball: null } }).ghostBall, null);
  });

  test('a malformed overlay is an error naming its path', () => {
    const bad = [
      [[], /overlay: expected an object/],
      [{ aim_line: [[0, 0]] }, /overlay\.aim_line: expected at least two/],
      [{ aim_line: [[0, 0], [1, 'x']] }, /overlay\.aim_line\[1\]: expected \[x, y\]/],
      [{ aim_line: [[0, 0], [1, 1]], ghost_ball: [1] }, /overlay\.ghost_ball: expected \[x, y\]/],
      [{ aim_line: [[0, 0], [1, Infinity]] }, /overlay\.aim_line\[1\]/],
    ];
    for (const [overlay, message] of bad) assert.throws(() => loadOverlay({ overlay }), message, JSON.stringify(overlay));
  });

  test('draws a solid line through every point, then a dashed circle of the ball radius at the ghost ball', () => {
    const result = withOverlay({ aim_line: [[0.5, 0.5], [2.5, 0.1], [1.7, 0.9]], ghost_ball: [1.7, 0.9] });
    const model = loadResult(result);
    const view = new View(tableLayout(model.table, model.radius).extent, 1000, 500);
    const ctx = recordingContext();
    drawOverlay(ctx, view, model.overlay, model.radius);
    const width = view.metres(OVERLAY_WIDTH);
    assert.deepEqual(ctx.calls, [
      ['beginPath'],
      ['moveTo', 0.5, 0.5],
      ['lineTo', 2.5, 0.1],
      ['lineTo', 1.7, 0.9],
      ['stroke', [], width],
      ['beginPath'],
      ['arc', 1.7, 0.9, model.radius, 0, 2 * Math.PI],
      ['stroke', GHOST_DASH.map((d) => view.metres(d)), width],
    ]);
  });

  test('without a ghost ball only the line is drawn', () => {
    const model = loadResult(withOverlay({ aim_line: [[0.5, 0.5], [1.5, 0.5]], ghost_ball: null }));
    const view = new View(tableLayout(model.table, model.radius).extent, 1000, 500);
    const ctx = recordingContext();
    drawOverlay(ctx, view, model.overlay, model.radius);
    assert.equal(ctx.calls.filter((c) => c[0] === 'arc').length, 0);
    assert.equal(ctx.calls.filter((c) => c[0] === 'stroke').length, 1);
  });
});
