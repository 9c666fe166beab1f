// End to end in headless Chromium (Debian's /usr/bin/chromium via
// playwright-core): pages made from real `cueball simulate` results load from
// file:// with no network and no console errors, draw the table, animate the
// balls and answer the controls. Checks read pixels of screenshots at places
// computed from the result (cloth at the table centre, a ball's colour where
// src/model.js puts it at time t) instead of comparing golden images.
//
// The cueball binary: $CUEBALL_BIN (default ../build/release/cueball); the
// pages it writes itself (`cueball view` and `simulate --html`) are tested too.
import assert from 'node:assert/strict';
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { after, before, describe, test } from 'node:test';
import { pathToFileURL } from 'node:url';
import {
  chromiumPath,
  cueball,
  cueballBinary,
  launchChromium,
  simulateToPage,
  tempDir,
  VIEWER_DIR,
} from '../scripts/cueball.mjs';
import { fillTemplate, TEMPLATE_PATH } from '../scripts/fill-template.mjs';
import { ballStyle } from '../src/balls.js';
import { loadResult, stateAt } from '../src/model.js';
import { decodePng } from './png.mjs';

const TIMEOUT = 60_000;
const dir = tempDir('cueball-viewer-e2e-');
let browser;

before(async () => {
  assert.ok(existsSync(cueballBinary()), `no cueball binary at ${cueballBinary()} (set CUEBALL_BIN)`);
  assert.ok(existsSync(chromiumPath()), `no Chromium at ${chromiumPath()} (apt-get install chromium)`);
  browser = await launchChromium();
});

after(async () => {
  if (browser) await browser.close();
});

// ---------------------------------------------------------------- helpers

/**
 * Opens a page from disk in a fresh context that allows no request but the
 * file itself, and records console errors and page errors.
 */
async function openPage(htmlPath, { width = 1200, height = 800, deviceScaleFactor = 1, waitReady = true } = {}) {
  const context = await browser.newContext({ viewport: { width, height }, deviceScaleFactor });
  const url = pathToFileURL(htmlPath).href;
  const problems = [];
  await context.route('**/*', (route) => {
    const requested = route.request().url();
    if (requested === url) return route.continue();
    problems.push(`request for ${requested}`);
    return route.abort();
  });
  const page = await context.newPage();
  page.setDefaultTimeout(10_000);
  page.on('request', (request) => {
    if (request.url() !== url) problems.push(`request for ${request.url()}`);
  });
  page.on('console', (message) => {
    if (message.type() === 'error') problems.push(`console error: ${message.text()}`);
  });
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  await page.goto(url);
  if (waitReady) {
    try {
      await page.waitForFunction(() => window.cueballViewer && window.cueballViewer.ready === true);
    } catch (error) {
      const text = (await page.locator('body').innerText()).slice(0, 200);
      throw new Error(
        `${htmlPath}: the viewer did not start (${error.message.split('\n')[0]}); ` +
          `problems: ${JSON.stringify(problems)}; page text: ${JSON.stringify(text)}`,
      );
    }
  }
  return {
    page,
    problems,
    async close() {
      assert.deepEqual(problems, [], 'no requests, console errors or page errors');
      await context.close();
    },
  };
}

/** RGBA of the screen at a viewport CSS pixel. */
async function pixel(page, [x, y]) {
  const png = await page.screenshot({
    clip: { x: Math.round(x) - 1, y: Math.round(y) - 1, width: 3, height: 3 },
    scale: 'css',
  });
  return decodePng(png).pixel(1, 1);
}

const hook = (page, expression, arg) => page.evaluate(expression, arg);
const time = (page) => hook(page, () => window.cueballViewer.time());

/**
 * Where the page draws table point (x, y), in viewport CSS pixels: the
 * mapping is recovered from the hook's pixels of two balls whose positions
 * are known, and checked on a third (y up on the screen).
 */
async function tableFrame(page, model, t) {
  const box = await page.locator('[data-testid=table-canvas]').boundingBox();
  const at = async (ball) => {
    const [px, py] = await hook(page, (id) => window.cueballViewer.ballPixel(id), ball.id);
    const s = stateAt(model, ball, t);
    return { px: box.x + px, py: box.y + py, x: s.x, y: s.y };
  };
  const [a, b, c] = await Promise.all(model.balls.slice(0, 3).map(at));
  const scale = Math.hypot(b.px - a.px, b.py - a.py) / Math.hypot(b.x - a.x, b.y - a.y);
  const toScreen = (x, y) => [a.px + (x - a.x) * scale, a.py - (y - a.y) * scale];
  const [cx, cy] = toScreen(c.x, c.y);
  assert.ok(Math.hypot(cx - c.px, cy - c.py) < 0.5, 'x to the right, y up, one scale');
  return { box, scale, toScreen, radius: model.radius * scale };
}

/** Viewport pixel of a ball's centre from the page's hook. */
async function ballOnScreen(page, id) {
  const box = await page.locator('[data-testid=table-canvas]').boundingBox();
  const [x, y] = await hook(page, (i) => window.cueballViewer.ballPixel(i), id);
  return [box.x + x, box.y + y];
}

/** A pixel of a ball of this colour: shaded darker towards the rim, lighter at the highlight. */
function looksLike(rgba, hex) {
  const n = parseInt(hex.slice(1), 16);
  const want = [(n >> 16) & 255, (n >> 8) & 255, n & 255];
  return want.every((c, i) => rgba[i] >= 0.6 * c - 12 && rgba[i] <= c + 45);
}

const isBlueCloth = ([r, g, b]) => b > r + 60 && b > g + 30;
const isGreenCloth = ([r, g, b]) => g > r + 50 && g > b + 30;
const show = (rgba) => `rgb(${rgba.slice(0, 3).join(', ')})`;

// ------------------------------------------------------------------ pages

describe('viewer in Chromium', { timeout: TIMEOUT }, () => {
  let breakPage; // the built-in 9-ball break, page made with fillTemplate()

  before(() => {
    breakPage = simulateToPage(dir, 'break');
  });

  test('the 9-ball break: table, balls, play, trails, events, scrubber, selection', async () => {
    const { result } = breakPage;
    const model = loadResult(result);
    const { page, close } = await openPage(breakPage.html);

    assert.equal(await time(page), 0);
    assert.equal(await hook(page, () => window.cueballViewer.duration()), result.end_time);
    assert.match(await page.locator('[data-testid=hud]').innerText(), /pool 9 ft/);

    // table and balls where the model says, at t = 0
    let frame = await tableFrame(page, model, 0);
    const centre = await pixel(page, frame.toScreen(result.table.length / 2, result.table.width / 2));
    assert.ok(isBlueCloth(centre), `cloth at the table centre: ${show(centre)}`);
    const cue = model.byId.get(0);
    const one = model.byId.get(1);
    const start = await ballOnScreen(page, 0);
    assert.ok(looksLike(await pixel(page, start), ballStyle('cue').colour), 'the cue ball is white');
    const onePos = stateAt(model, one, 0);
    const [ox, oy] = frame.toScreen(onePos.x, onePos.y);
    const onePixel = await pixel(page, [ox + 0.75 * frame.radius, oy]);
    assert.ok(looksLike(onePixel, ballStyle('1').colour), `the 1 is yellow: ${show(onePixel)}`);

    // play with the button; time advances and the cue ball moves
    await page.click('[data-testid=play]');
    await page.waitForFunction(() => window.cueballViewer.time() > 0.3);
    await page.click('[data-testid=play]');
    assert.equal(await page.locator('[data-testid=play]').getAttribute('data-state'), 'paused');
    const t1 = await time(page);
    assert.ok(t1 > 0.3 && t1 < result.end_time, `paused at ${t1}`);
    frame = await tableFrame(page, model, t1);
    const cueNow = stateAt(model, cue, t1);
    const moved = frame.toScreen(cueNow.x, cueNow.y);
    const hooked = await ballOnScreen(page, 0);
    assert.ok(Math.hypot(moved[0] - hooked[0], moved[1] - hooked[1]) < 0.5, 'hook agrees with the model');
    assert.ok(Math.hypot(moved[0] - start[0], moved[1] - start[1]) > 4 * frame.radius, 'the cue ball moved');
    assert.ok(looksLike(await pixel(page, moved), ballStyle('cue').colour), 'the cue ball is drawn where it is now');

    // its trail: dashed (sliding) along its path from the start, gone when trails are off
    const trailPoints = [];
    for (let k = 1; k <= 16; ++k) trailPoints.push([start[0] + ((moved[0] - start[0]) * k) / 20, start[1]]);
    const lit = async () => {
      let n = 0;
      for (const p of trailPoints) if (!isBlueCloth(await pixel(page, p))) n += 1;
      return n;
    };
    const withTrails = await lit();
    assert.ok(withTrails >= 4 && withTrails < trailPoints.length, `dashed trail: ${withTrails} of 16 points lit`);
    await page.click('[data-testid=toggle-trails]');
    assert.equal(await lit(), 0, 'no trail when trails are off');
    const vacated = await pixel(page, start);
    assert.ok(isBlueCloth(vacated), `cloth where the cue ball was: ${show(vacated)}`);
    await page.click('[data-testid=toggle-trails]');

    // an event in the list: seeks exactly to it and draws its ball there
    const cushion = model.events.find((e) => e.type === 'ball_cushion');
    await page.click(`[data-testid=event-${cushion.index}]`);
    assert.equal(await time(page), cushion.time);
    assert.ok(
      Math.abs(Number(await page.locator('[data-testid=scrubber]').inputValue()) - cushion.time) < 1e-9,
      'the scrubber follows',
    );
    assert.match(await page.locator(`[data-testid=event-${cushion.index}]`).locator('..').getAttribute('class'), /current/);
    const hitter = model.byId.get(cushion.balls[0]);
    frame = await tableFrame(page, model, cushion.time);
    const h = stateAt(model, hitter, cushion.time);
    const [hx, hy] = frame.toScreen(h.x, h.y);
    const hitterPixel = await pixel(page, [hx + 0.75 * frame.radius, hy]);
    assert.ok(looksLike(hitterPixel, ballStyle(hitter.name).colour), `ball ${hitter.name} at the cushion: ${show(hitterPixel)}`);

    // motion transitions are listed on request
    const transition = model.events.find((e) => e.type === 'slide_to_roll');
    const transitionRow = page.locator(`[data-testid=event-${transition.index}]`);
    assert.equal(await transitionRow.isVisible(), false);
    await page.click('[data-testid=toggle-transitions]');
    assert.equal(await transitionRow.isVisible(), true);
    await page.click('[data-testid=toggle-transitions]');
    assert.equal(await transitionRow.isVisible(), false);

    // a marker on the timeline: the key event farthest from its neighbours
    const keys = model.events.filter((e) => ['ball_ball', 'ball_cushion', 'ball_pocket'].includes(e.type));
    const gap = (i) => Math.min(i > 0 ? keys[i].time - keys[i - 1].time : Infinity, i + 1 < keys.length ? keys[i + 1].time - keys[i].time : Infinity);
    const lonely = keys.reduce((best, e, i) => (gap(i) > gap(best) ? i : best), 0);
    await page.click(`[data-testid=event-marker-${keys[lonely].index}]`);
    assert.equal(await time(page), keys[lonely].time);

    // next-event button: the first contact after now
    await page.click(`[data-testid=event-${cushion.index}]`);
    await page.click('[data-testid=next-event]');
    const next = keys.find((e) => e.time > cushion.time + 1e-9);
    assert.equal(await time(page), next.time);

    // the scrubber: a click and a drag set the time by position
    const bar = await page.locator('[data-testid=scrubber]').boundingBox();
    const duration = result.end_time;
    await page.mouse.click(bar.x + 0.25 * bar.width, bar.y + bar.height / 2);
    const clicked = await time(page);
    assert.ok(Math.abs(clicked - 0.25 * duration) < 0.03 * duration, `clicked at a quarter: ${clicked}`);
    await page.mouse.move(bar.x + 0.25 * bar.width, bar.y + bar.height / 2);
    await page.mouse.down();
    await page.mouse.move(bar.x + 0.75 * bar.width, bar.y + bar.height / 2, { steps: 6 });
    await page.mouse.up();
    const dragged = await time(page);
    assert.ok(Math.abs(dragged - 0.75 * duration) < 0.03 * duration, `dragged to three quarters: ${dragged}`);
    assert.match(await page.locator('[data-testid=time]').innerText(), new RegExp(dragged.toFixed(3)));

    // select a ball by clicking it on the table, then from the list
    await page.mouse.click(...(await ballOnScreen(page, 9)));
    assert.equal(await page.locator('[data-testid=ball-select]').inputValue(), '9');
    assert.match(await page.locator('[data-testid=ball-readout]').innerText(), /^9 · /);
    await page.selectOption('[data-testid=ball-select]', '1');
    assert.match(await page.locator('[data-testid=ball-readout]').innerText(), /^1 · /);

    // the plot: a click seeks to its time; the readout gives the exact speed there
    const plot = await page.locator('[data-testid=plot]').boundingBox();
    await page.mouse.click(plot.x + 44 + 0.5 * (plot.width - 54), plot.y + plot.height / 2);
    const plotted = await time(page);
    assert.ok(Math.abs(plotted - duration / 2) < 0.02 * duration, `plot click at the middle: ${plotted}`);
    const speed = Math.hypot(stateAt(model, one, plotted).vx, stateAt(model, one, plotted).vy);
    assert.match(await page.locator('[data-testid=ball-readout]').innerText(), new RegExp(`\\|v\\| = ${speed.toFixed(3)} m/s`));

    // the keyboard: space plays and pauses
    await page.keyboard.press('Space');
    assert.equal(await page.locator('[data-testid=play]').getAttribute('data-state'), 'playing');
    await page.keyboard.press('Space');
    assert.equal(await page.locator('[data-testid=play]').getAttribute('data-state'), 'paused');

    // responsive: a narrow window keeps the whole table in the canvas
    await page.setViewportSize({ width: 640, height: 900 });
    await page.waitForFunction(() => document.getElementById('table').width === document.getElementById('table').clientWidth);
    await hook(page, () => window.cueballViewer.seek(0));
    frame = await tableFrame(page, model, 0);
    for (const [x, y] of [[-0.05, -0.05], [result.table.length + 0.05, result.table.width + 0.05]]) {
      const [px, py] = frame.toScreen(x, y);
      assert.ok(px >= frame.box.x && px <= frame.box.x + frame.box.width, 'table fits across');
      assert.ok(py >= frame.box.y && py <= frame.box.y + frame.box.height, 'table fits down');
    }
    assert.ok(isBlueCloth(await pixel(page, frame.toScreen(result.table.length / 2, result.table.width / 2))));
    await close();
  });

  test('crisp on a high-density screen: the canvas has devicePixelRatio pixels per CSS pixel', async () => {
    const { page, close } = await openPage(breakPage.html, { deviceScaleFactor: 2 });
    const sizes = await page.evaluate(() => {
      const c = document.getElementById('table');
      return [c.width, c.clientWidth, c.height, c.clientHeight, window.devicePixelRatio];
    });
    assert.deepEqual(sizes, [2 * sizes[1], sizes[1], 2 * sizes[3], sizes[3], 2]);
    assert.ok(looksLike(await pixel(page, await ballOnScreen(page, 0)), ballStyle('cue').colour));
    await close();
  });

  test('a pocketed ball is drawn until it drops into its pocket', async () => {
    const { result, html } = simulateToPage(dir, 'cut', resolve(VIEWER_DIR, 'test/fixtures/scenarios/cut-shot.json'));
    const model = loadResult(result);
    const one = model.balls.find((b) => b.name === '1');
    assert.ok(one.pocketed, 'the cut shot pockets the 1');
    const { page, close } = await openPage(html);
    await hook(page, (t) => window.cueballViewer.seek(t), one.pocketTime - 0.05);
    let frame = await tableFrame(page, model, one.pocketTime - 0.05);
    let s = stateAt(model, one, one.pocketTime - 0.05);
    let [x, y] = frame.toScreen(s.x, s.y);
    assert.ok(looksLike(await pixel(page, [x + 0.75 * frame.radius, y]), ballStyle('1').colour), 'the 1 on its way');
    await hook(page, (t) => window.cueballViewer.seek(t), one.pocketTime + 1);
    s = stateAt(model, one, one.pocketTime + 1);
    [x, y] = frame.toScreen(s.x, s.y);
    const gone = await pixel(page, [x, y]);
    assert.ok(!looksLike(gone, ballStyle('1').colour), `the 1 has gone: ${show(gone)}`);
    assert.match(await page.locator('[data-testid=event-list]').innerText(), /1 pocketed \(top-right\)/);
    await close();
  });

  test('a snooker break and a carom table (no pockets) load and draw', async () => {
    for (const [name, cloth] of [['snooker-break', isGreenCloth], ['carom-side-spin', isBlueCloth]]) {
      const { result, html } = simulateToPage(dir, name, resolve(VIEWER_DIR, `test/fixtures/scenarios/${name}.json`));
      const model = loadResult(result);
      const { page, close } = await openPage(html);
      const frame = await tableFrame(page, model, 0);
      const spot = await pixel(page, frame.toScreen(result.table.length * 0.6, result.table.width * 0.3));
      assert.ok(cloth(spot), `${name}: cloth ${show(spot)}`);
      for (const ball of model.balls) {
        const style = ballStyle(ball.name);
        const s = stateAt(model, ball, 0);
        const [x, y] = frame.toScreen(s.x, s.y);
        const at = await pixel(page, style.label ? [x + 0.75 * frame.radius, y] : [x, y]);
        assert.ok(looksLike(at, style.colour), `${name}: ${ball.name} ${show(at)}`);
      }
      await hook(page, () => window.cueballViewer.seek(1));
      await page.click('[data-testid=play]');
      await page.waitForFunction(() => window.cueballViewer.time() > 1.1);
      await close();
    }
  });

  test('stripes show white caps, solids are coloured all over (the 1 and the 9 differ)', async () => {
    const model = loadResult(breakPage.result);
    const { page, close } = await openPage(breakPage.html);
    const frame = await tableFrame(page, model, 0);
    const at = async (id, dx, dy) => {
      const s = stateAt(model, model.byId.get(id), 0);
      const [x, y] = frame.toScreen(s.x, s.y);
      return pixel(page, [x + dx * frame.radius, y + dy * frame.radius]);
    };
    const white = '#fbfaf5';
    const oneTop = await at(1, 0, -0.78);
    const nineTop = await at(9, 0, -0.78);
    const nineSide = await at(9, 0.8, 0);
    assert.ok(looksLike(oneTop, ballStyle('1').colour), `the 1 is yellow at the top: ${show(oneTop)}`);
    assert.ok(looksLike(nineTop, white) && !looksLike(nineTop, ballStyle('1').colour), `the 9 has a white cap: ${show(nineTop)}`);
    assert.ok(looksLike(nineSide, ballStyle('9').colour), `the 9's band is yellow: ${show(nineSide)}`);
    const eight = await at(8, 0.8, 0);
    assert.ok(looksLike(eight, '#121212'), `the 8 is black: ${show(eight)}`);
    await close();
  });

  test('a game document: one row per shot, rows, [ ] and the buttons load shots, decisions show the table', async () => {
    const cut = simulateToPage(dir, 'game-cut', resolve(VIEWER_DIR, 'test/fixtures/scenarios/cut-shot.json'));
    const game = {
      game: {
        kind: 'nine_ball',
        players: ['planner', 'ghost_ball'],
        winner: 1,
        end_reason: 'the 9 potted legally (WPA 2.1)',
        shots: [
          { player: 0, caption: 'shot 1, player 0: nothing potted', scores: [0, 0], foul: null, result: breakPage.result },
          { player: 1, caption: 'shot 2, player 1: 1 potted; foul: scratch (WPA 6.1)', scores: [0, 0], foul: 'scratch', result: cut.result },
          { player: 0, caption: 'shot 3, player 0: pass (WPA 2.4)', scores: [0, 0], decision: 'pass' },
          { player: 1, caption: 'shot 4, player 1: 9 potted (WPA 2.1)', scores: [0, 1], foul: null, result: breakPage.result },
        ],
      },
    };
    const html = join(dir, 'game.html');
    writeFileSync(html, fillTemplate(readFileSync(TEMPLATE_PATH, 'utf8'), JSON.stringify(game)));
    const { page, close } = await openPage(html);
    const shot = () => hook(page, () => window.cueballViewer.shot());
    const duration = () => hook(page, () => window.cueballViewer.duration());
    const rows = page.locator('[data-testid=shot-list] li');
    assert.equal(await rows.count(), 4, 'one row per shot');
    assert.equal(await shot(), 0);
    assert.equal(await duration(), breakPage.result.end_time);
    assert.match(await rows.nth(0).getAttribute('class'), /current/);
    assert.match(await page.locator('[data-testid=game-result]').innerText(), /player 1 \(ghost_ball\) wins/);
    assert.match(await page.locator('[data-testid=shot-1]').innerText(), /foul: scratch/);

    // a click on a row loads its result
    await page.click('[data-testid=shot-1]');
    assert.equal(await shot(), 1);
    assert.equal(await duration(), cut.result.end_time);
    assert.notEqual(cut.result.end_time, breakPage.result.end_time);
    assert.match(await rows.nth(1).getAttribute('class'), /current/);
    assert.doesNotMatch(await rows.nth(0).getAttribute('class'), /current/);
    assert.equal(await page.locator('[data-testid=shot-caption]').innerText(), game.game.shots[1].caption);
    assert.equal(await page.locator('[data-testid=event-list] li').count(), cut.result.events.length, 'the events of this shot only');
    assert.equal(await page.locator('[data-testid=ball-select] option').count(), cut.result.balls.length);

    // the loaded shot plays (its controls are bound once: a double binding would toggle twice)
    await page.click('[data-testid=play]');
    assert.equal(await page.locator('[data-testid=play]').getAttribute('data-state'), 'playing');
    await page.waitForFunction(() => window.cueballViewer.time() > 0.05);

    // ] : the decision shows the table as it stands (the shot before at its end) with the caption
    await page.locator('body').press(']');
    assert.equal(await shot(), 2);
    assert.equal(await hook(page, () => window.cueballViewer.time()), cut.result.end_time);
    assert.equal(await page.locator('[data-testid=shot-caption]').innerText(), 'shot 3, player 0: pass (WPA 2.4)');
    assert.match(await rows.nth(2).getAttribute('class'), /decision/);
    const centre = await ballOnScreen(page, 0);
    const cue = cut.result.balls.find((b) => b.id === 0);
    if (!cue.pocketed) assert.ok(looksLike(await pixel(page, centre), ballStyle('cue').colour), 'the cue ball where it stopped');

    await page.click('[data-testid=next-shot]');
    assert.equal(await shot(), 3);
    assert.equal(await page.locator('[data-testid=next-shot]').isDisabled(), true);
    await page.locator('body').press('[');
    await page.click('[data-testid=prev-shot]');
    assert.equal(await shot(), 1);
    assert.equal(await duration(), cut.result.end_time);
    await close();
  });

  test('a game page written by `cueball game play --html`: every shot loads, decisions and snooker too', async () => {
    for (const [kind, players] of [['nine_ball', 'ghost_ball,random'], ['snooker', 'ghost_ball,ghost_ball']]) {
      const html = join(dir, `played-${kind}.html`);
      cueball(['game', 'play', '--game', kind, '--players', players, '--seed', '2', '--html', html]);
      const text = readFileSync(html, 'utf8');
      const open = '<script type="application/json" id="cueball-result">';
      const from = text.indexOf(open) + open.length;
      const doc = JSON.parse(text.slice(from, text.indexOf('</script>', from)));
      const shots = doc.game.shots;
      const { page, close } = await openPage(html);
      assert.equal(await page.locator('[data-testid=shot-list] li').count(), shots.length, `${kind}: one row per shot`);
      // every shot, by ]: its own result (a decision: the table at rest, duration 0)
      for (let i = 0; i < shots.length; ++i) {
        if (i > 0) await page.locator('body').press(']');
        assert.equal(await hook(page, () => window.cueballViewer.shot()), i);
        assert.equal(await hook(page, () => window.cueballViewer.duration()), shots[i].result.end_time, `${kind} shot ${i}`);
      }
      assert.equal(await page.locator('[data-testid=shot-caption]').innerText(), shots[shots.length - 1].caption);
      await close();
    }
  });

  test('a game page in a narrow window keeps the table visible', async () => {
    const game = { game: { kind: 'nine_ball', players: ['a', 'b'], winner: null, end_reason: '', shots: [
      { player: 0, caption: 'shot 1, player 0: nothing potted', scores: [0, 0], foul: null, result: breakPage.result },
    ] } };
    const html = join(dir, 'game-narrow.html');
    writeFileSync(html, fillTemplate(readFileSync(TEMPLATE_PATH, 'utf8'), JSON.stringify(game)));
    const { page, close } = await openPage(html, { width: 600, height: 900 });
    const box = await page.locator('[data-testid=table-canvas]').boundingBox();
    assert.ok(box.width > 500 && box.height > 200, `table ${box.width}×${box.height}`);
    assert.ok(await page.locator('[data-testid=shot-list]').isVisible());
    assert.match(await page.locator('[data-testid=game-result]').innerText(), /no result yet/);
    await close();
  });

  test('the template alone asks for a result file, then shows it', async () => {
    const { page, close } = await openPage(TEMPLATE_PATH, { waitReady: false });
    await page.locator('[data-testid=message]').waitFor();
    assert.match(await page.locator('[data-testid=message]').innerText(), /No shot in this page/);
    assert.equal(await page.evaluate(() => window.cueballViewer), undefined);
    await page.setInputFiles('[data-testid=open-result]', breakPage.json);
    await page.waitForFunction(() => window.cueballViewer && window.cueballViewer.ready === true);
    assert.equal(await hook(page, () => window.cueballViewer.duration()), breakPage.result.end_time);
    await close();
  });

  test('a page written by `cueball plan-shot --html` draws the aim line and the ghost ball', async () => {
    const scenario = join(dir, 'cut-plan.json');
    writeFileSync(
      scenario,
      JSON.stringify({
        table: 'pool_9ft',
        balls: [
          { id: 0, name: 'cue', position: [1.55, 0.7] },
          { id: 1, name: '1', position: [2.214, 0.944] },
          { id: 9, name: '9', position: [0.8, 1.0] },
        ],
      }),
    );
    const planned = join(dir, 'planned.json');
    const html = join(dir, 'plan.html');
    cueball(['plan-shot', scenario, '--ball', '1', '--html', html, '--scenario-out', planned]);
    const bare = join(dir, 'plan-bare.html'); // the same shot without the overlay
    cueball(['simulate', planned, '--html', bare]);
    const embedded = /id="cueball-result">([^<]*)<\/script>/.exec(readFileSync(html, 'utf8'));
    const result = JSON.parse(embedded[1]);
    const model = loadResult(result);
    assert.ok(model.overlay && model.overlay.ghostBall, 'the page carries the overlay');
    const [start, ghost] = model.overlay.aimLine;
    const middle = [(start[0] + ghost[0]) / 2, (start[1] + ghost[1]) / 2];
    // brightest red channel around a point: the white line over the blue cloth
    const brightest = async (page, [x, y]) => {
      const png = decodePng(
        await page.screenshot({ clip: { x: Math.round(x) - 2, y: Math.round(y) - 2, width: 5, height: 5 }, scale: 'css' }),
      );
      let red = 0;
      for (let i = 0; i < 5; ++i) for (let j = 0; j < 5; ++j) red = Math.max(red, png.pixel(i, j)[0]);
      return red;
    };
    const seen = {};
    for (const page_ of [html, bare]) {
      const { page, close } = await openPage(page_);
      const frame = await tableFrame(page, model, 0);
      const ghostPixel = await hook(page, () => window.cueballViewer.ghostPixel());
      if (page_ === html) {
        const [gx, gy] = frame.toScreen(ghost[0], ghost[1]);
        assert.ok(Math.hypot(frame.box.x + ghostPixel[0] - gx, frame.box.y + ghostPixel[1] - gy) < 0.5, 'ghost ball');
      } else {
        assert.equal(ghostPixel, null, 'no overlay, no ghost ball');
      }
      seen[page_] = await brightest(page, frame.toScreen(middle[0], middle[1]));
      await close();
    }
    assert.ok(seen[html] > seen[bare] + 60, `the aim line: red ${seen[html]} on it, ${seen[bare]} without the overlay`);
    assert.ok(seen[bare] < 90, `cloth without the overlay: red ${seen[bare]}`);
  });

  test('pages written by `cueball view` and `cueball simulate --html`', async () => {
    const viewed = join(dir, 'viewed.html');
    cueball(['view', breakPage.json, '-o', viewed]);
    const simulated = join(dir, 'simulated.html');
    cueball(['simulate', '--html', simulated]);
    const model = loadResult(breakPage.result);
    for (const html of [viewed, simulated]) {
      const { page, close } = await openPage(html);
      assert.equal(await hook(page, () => window.cueballViewer.duration()), breakPage.result.end_time, html);
      const frame = await tableFrame(page, model, 0);
      const centre = await pixel(page, frame.toScreen(breakPage.result.table.length / 2, breakPage.result.table.width / 2));
      assert.ok(isBlueCloth(centre), `${html}: cloth at the centre ${show(centre)}`);
      const start = await ballOnScreen(page, 0);
      await page.click('[data-testid=play]');
      await page.waitForFunction(() => window.cueballViewer.time() > 0.2);
      await page.click('[data-testid=play]');
      const now = await ballOnScreen(page, 0);
      assert.ok(Math.hypot(now[0] - start[0], now[1] - start[1]) > 2 * frame.radius, `${html}: the cue ball moved`);
      assert.ok(looksLike(await pixel(page, now), ballStyle('cue').colour), `${html}: drawn where it is`);
      const event = model.events.find((e) => e.type === 'ball_ball');
      await page.click(`[data-testid=event-${event.index}]`);
      assert.equal(await time(page), event.time);
      await close();
    }
  });
});
