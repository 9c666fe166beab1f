// The game document (src/game.js): read and checked, decisions shown on the
// table as it stands; the balls' looks (src/balls.js) for pool, snooker and carom.
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { ballLook, ballStyle } from '../src/balls.js';
import { consideredLine, gameOutcome, isGame, loadGame } from '../src/game.js';
import { loadResult } from '../src/model.js';
import { readFixture } from './helpers.mjs';

const breakResult = readFixture('nine-ball-break');
const cutResult = readFixture('cut-shot');

function doc(shots, extra = {}) {
  return { game: { kind: 'nine_ball', players: ['planner', 'ghost_ball'], winner: null, end_reason: '', shots, ...extra } };
}

describe('game document', () => {
  test('one entry per shot; a decision shows the shot before it at its end', () => {
    const game = loadGame(
      doc([
        { player: 0, caption: 'break', scores: [0, 0], foul: null, result: breakResult },
        { player: 1, caption: 'push-out', scores: [0, 0], foul: null, result: cutResult },
        { player: 0, caption: 'pass', scores: [0, 0], decision: 'pass' },
        { player: 1, caption: 'scratch', scores: [0, 0], foul: 'scratch', result: breakResult },
      ]),
    );
    assert.equal(game.entries.length, 4);
    assert.deepEqual(game.entries.map((e) => e.decision), [null, null, 'pass', null]);
    assert.equal(game.entries[2].result, cutResult);
    assert.equal(game.entries[2].atEnd, true);
    assert.equal(game.entries[1].atEnd, false);
    assert.equal(game.entries[3].foul, 'scratch');
    for (const e of game.entries) assert.ok(loadResult(e.result).duration >= 0);
  });

  test('a decision with its own table keeps it', () => {
    const game = loadGame(doc([{ player: 0, caption: 'pass', scores: [0, 0], decision: 'pass', result: cutResult }]));
    assert.equal(game.entries[0].result, cutResult);
  });

  test('a decision before any shot has nothing to show', () => {
    const game = loadGame(doc([{ player: 0, caption: 'rerack', scores: [0, 0], decision: 'rerack' }]));
    assert.equal(game.entries[0].result, null);
  });

  test('the outcome names the winner and the reason', () => {
    assert.equal(gameOutcome(loadGame(doc([], { winner: 1, end_reason: 'the 9 (WPA 2.1)' }))), 'player 1 (ghost_ball) wins: the 9 (WPA 2.1)');
    assert.equal(gameOutcome(loadGame(doc([], { end_reason: 'max_shots reached' }))), 'no winner: max_shots reached');
    assert.equal(gameOutcome(loadGame(doc([]))), 'no result yet');
  });

  test('a one-shot result is not a game', () => {
    assert.equal(isGame(breakResult), false);
    assert.equal(isGame(doc([])), true);
  });

  test("an agent's reasoning is read with its estimates; none is null", () => {
    const reasoning = {
      summary: 'direct 3 bottom-right (window 0.910, screen 0.880)',
      considered: [
        { what: 'direct 3 bottom-right', estimate: 0.88, next_estimate: 0.75 },
        { what: 'bank 3 top-left', estimate: 0.41 },
        { what: 'safety' },
      ],
    };
    const game = loadGame(
      doc([
        { player: 0, caption: 'break', scores: [0, 0], foul: null, result: breakResult },
        { player: 1, caption: 'a pot', scores: [0, 0], foul: null, result: cutResult, reasoning },
      ]),
    );
    assert.equal(game.entries[0].reasoning, null);
    const r = game.entries[1].reasoning;
    assert.equal(r.summary, reasoning.summary);
    assert.deepEqual(
      r.considered.map(consideredLine),
      ['direct 3 bottom-right: P 0.880, next 0.750', 'bank 3 top-left: P 0.410', 'safety'],
    );
    const bad = (value) => doc([{ player: 0, caption: 'x', scores: [0, 0], result: cutResult, reasoning: value }]);
    assert.throws(() => loadGame(bad({ summary: 3 })), /game\.shots\[0\]\.reasoning\.summary/);
    assert.throws(() => loadGame(bad({ considered: [{ what: 'x', estimate: 1.5 }] })), /reasoning\.considered\[0\]\.estimate/);
    assert.throws(() => loadGame(bad({ considered: [{}] })), /reasoning\.considered\[0\]\.what/);
  });

  test('errors name the path', () => {
    assert.throws(() => loadGame({ game: { players: ['a'], shots: [] } }), /game\.players: expected two names/);
    assert.throws(() => loadGame(doc([{ player: 2, caption: 'x', scores: [0, 0], result: breakResult }])), /game\.shots\[0\]\.player/);
    assert.throws(() => loadGame(doc([{ player: 0, caption: 'x', scores: [0], result: breakResult }])), /game\.shots\[0\]\.scores/);
    assert.throws(() => loadGame(doc([{ player: 0, caption: 'x', scores: [0, 0] }])), /game\.shots\[0\]\.result/);
    assert.throws(() => loadGame(doc([], { winner: 3 })), /game\.winner/);
  });
});

describe('ball looks', () => {
  test('pool: 1..8 solids, 9..15 stripes of the same colours, the 8 black', () => {
    for (let k = 1; k <= 7; ++k) {
      const solid = ballStyle(String(k));
      const stripe = ballStyle(String(k + 8));
      assert.equal(solid.stripe, false);
      assert.equal(stripe.stripe, true);
      assert.equal(stripe.colour, solid.colour);
      assert.equal(stripe.label, String(k + 8));
    }
    assert.deepEqual(ballStyle('8'), { colour: '#121212', stripe: false, label: '8', disc: true });
  });

  test('the stripe leaves white caps and the number disc is legible at every size', () => {
    for (const r of [5, 6.6, 8, 10, 14, 30]) {
      const look = ballLook(r);
      // white caps: the band leaves at least 40 % of the radius above and below it
      assert.ok(look.band <= 0.6, `band at r=${r}`);
      // the number's disc is wide enough for two digits of the font
      assert.ok(look.disc >= 0.45 && look.disc * r * 2 >= 0.9 * look.font2 * r, `disc at r=${r}`);
      // figures at least 6 px high where the ball is small (the draw clamps to 6 px)
      assert.ok(look.font1 >= look.font2);
    }
    assert.ok(ballLook(6.6).disc > ballLook(20).disc, 'larger disc on small balls');
  });

  test('snooker colours and carom balls by name', () => {
    for (let k = 1; k <= 15; ++k) assert.equal(ballStyle(`red${k}`).colour, ballStyle('red').colour);
    const colours = ['yellow', 'green', 'brown', 'blue', 'pink', 'black'].map((n) => ballStyle(n).colour);
    assert.equal(new Set(colours).size, 6, 'six different colours');
    for (const n of ['yellow', 'green', 'brown', 'blue', 'pink', 'black', 'red1', 'white', 'red']) {
      assert.equal(ballStyle(n).label, '', `${n} has no label`);
      assert.equal(ballStyle(n).stripe, false);
    }
    // three-cushion: white, yellow, red (src/games/three_cushion.cpp)
    assert.notEqual(ballStyle('white').colour, ballStyle('yellow').colour);
    assert.notEqual(ballStyle('yellow').colour, ballStyle('red').colour);
  });
});
