// The viewer: the table canvas with balls and trails, the playback controls,
// the event timeline and the selected ball's panel, kept in step with one
// playback clock.

import { ballStyle, drawBall, trailColour } from './balls.js';
import { bindControls, showPlayerState } from './controls.js';
import { describeGeometry } from './format.js';
import { tableLayout, View } from './geometry.js';
import { pathPieces, phaseAt, POCKET_DROP_TIME, speedSeries, stateAt, TRANSITION_EVENTS } from './model.js';
import { angularSpeed, speed } from './motion.js';
import { drawOverlay } from './overlay.js';
import { Player } from './player.js';
import { SpeedPlot } from './plot.js';
import { drawTable, tableTheme } from './table-draw.js';
import { Timeline } from './timeline.js';
import { drawTrail } from './trails.js';

/** Seconds a contact stays marked on the table after it happens. */
const FLASH_TIME = 0.3;

export class Viewer {
  /**
   * @param {Record<string, HTMLElement>} el elements of template.html
   * @param {ReturnType<import('./model.js').loadResult>} model
   */
  constructor(el, model) {
    this.el = el;
    // every listener of this viewer goes with it (destroy(): the game page
    // replaces the viewer when another shot is loaded)
    this.abort = new AbortController();
    const signal = this.abort.signal;
    this.model = model;
    this.layout = tableLayout(model.table, model.radius);
    this.theme = tableTheme(model.table.name);
    this.names = describeGeometry(model.table);
    this.balls = model.balls.map((ball) => {
      const style = ballStyle(ball.name);
      return { ball, style, trailColour: trailColour(style), path: pathPieces(model, ball) };
    });
    this.flashes = this.contactFlashes();
    this.view = null;
    this.tableImage = null;
    this.showTrails = el.trails.checked;

    this.player = new Player(model.duration, () => this.render());
    this.plot = new SpeedPlot(el.plot, model.duration, (t) => this.seek(t), signal);
    this.timeline = new Timeline(
      { track: el.timeline, list: el.eventList, legend: el.timelineLegend },
      model,
      this.names,
      (event) => this.seek(event.time),
    );
    const keyTimes = model.events.filter((e) => !TRANSITION_EVENTS.has(e.type)).map((e) => e.time);
    bindControls(el, this.player, {
      previous: (t) => last(keyTimes.filter((k) => k < t - 1e-9)),
      next: (t) => keyTimes.find((k) => k > t + 1e-9) ?? null,
    }, signal);

    el.hudTable.textContent = model.table.name;
    document.title = `cueball – ${model.table.name}`;
    this.fillBallList();
    el.ballSelect.addEventListener('change', () => this.select(Number(el.ballSelect.value)), { signal });
    el.canvas.addEventListener('click', (e) => this.pick(e), { signal });
    el.trails.addEventListener('change', () => {
      this.showTrails = el.trails.checked;
      this.render();
    }, { signal });
    const showTransitions = () => this.timeline.showTransitions(el.showTransitions.checked);
    el.showTransitions.addEventListener('change', showTransitions, { signal });
    showTransitions();

    const cue = model.balls.find((b) => b.name === 'cue') || model.balls[0];
    this.selected = null;
    this.select(cue ? cue.id : null);
    this.resizeObserver = new ResizeObserver(() => this.resize());
    this.resizeObserver.observe(el.stage);
    this.resize();
  }

  /** Stops this viewer and empties what it filled, for another to take the elements. */
  destroy() {
    this.player.pause();
    this.player.onChange = () => {};
    this.abort.abort();
    this.resizeObserver.disconnect();
    const el = this.el;
    for (const e of [el.ballSelect, el.speed, el.timeline, el.eventList, el.timelineLegend, el.readout]) {
      e.replaceChildren();
    }
  }

  /** Pauses and jumps to time t (s). */
  seek(t) {
    this.player.pause();
    this.player.seek(t);
  }

  /** CSS pixel [x, y] in the table canvas of the overlay's ghost ball (null without one). */
  ghostPixel() {
    const ghost = this.model.overlay && this.model.overlay.ghostBall;
    if (!ghost || !this.view) return null;
    return this.view.toCss(ghost[0], ghost[1]);
  }

  /** CSS pixel [x, y] in the table canvas of a ball's centre now. */
  ballPixel(id) {
    const ball = this.model.byId.get(id);
    if (!ball || !this.view) return null;
    const s = stateAt(this.model, ball, this.player.time);
    return this.view.toCss(s.x, s.y);
  }

  fillBallList() {
    for (const { ball } of this.balls) {
      const option = document.createElement('option');
      option.value = String(ball.id);
      option.textContent = ball.pocketed
        ? `${ball.name} (pocketed ${ball.pocketName}, ${ball.pocketTime.toFixed(3)} s)`
        : ball.name;
      this.el.ballSelect.append(option);
    }
  }

  select(id) {
    const entry = this.balls.find((b) => b.ball.id === id);
    this.selected = entry || null;
    if (entry) {
      this.el.ballSelect.value = String(id);
      this.plot.setSeries(speedSeries(this.model, entry.ball), entry.trailColour);
    }
    this.render();
  }

  // Selects the ball under a click on the table.
  pick(e) {
    if (!this.view) return;
    const rect = this.el.canvas.getBoundingClientRect();
    const [x, y] = this.view.toTable(e.clientX - rect.left, e.clientY - rect.top);
    const reach = this.model.radius + this.view.metres(4);
    let best = null;
    let bestD = reach;
    for (const { ball } of this.balls) {
      if (!this.visible(ball, this.player.time)) continue;
      const s = stateAt(this.model, ball, this.player.time);
      const d = Math.hypot(s.x - x, s.y - y);
      if (d <= bestD) [best, bestD] = [ball, d];
    }
    if (best) this.select(best.id);
  }

  visible(ball, t) {
    return !ball.pocketed || t < ball.pocketTime + POCKET_DROP_TIME;
  }

  resize() {
    const canvas = this.el.canvas;
    const dpr = window.devicePixelRatio || 1;
    const w = canvas.clientWidth;
    const h = canvas.clientHeight;
    if (w === 0 || h === 0) return;
    canvas.width = Math.round(w * dpr);
    canvas.height = Math.round(h * dpr);
    this.view = new View(this.layout.extent, w, h, dpr);
    // the table does not change: draw it once per size
    const image = document.createElement('canvas');
    image.width = canvas.width;
    image.height = canvas.height;
    drawTable(image.getContext('2d'), this.model.table, this.layout, this.view, this.theme);
    this.tableImage = image;
    this.plot.resize();
    this.render();
  }

  render() {
    const t = this.player.time;
    this.renderTable(t);
    showPlayerState(this.el, t, this.player.playing, this.model.duration);
    this.el.hudTime.textContent = `t = ${t.toFixed(3)} s`;
    this.timeline.update(t);
    this.renderSelected(t);
  }

  renderTable(t) {
    const view = this.view;
    if (!view) return;
    const ctx = this.el.canvas.getContext('2d');
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.clearRect(0, 0, this.el.canvas.width, this.el.canvas.height);
    ctx.drawImage(this.tableImage, 0, 0);

    const now = this.balls.map(({ ball }) => stateAt(this.model, ball, t));
    if (this.model.overlay) {
      view.applyTable(ctx);
      drawOverlay(ctx, view, this.model.overlay, this.model.radius);
    }
    if (this.showTrails) {
      view.applyTable(ctx);
      this.balls.forEach((b, i) => {
        const selected = b === this.selected;
        drawTrail(ctx, view, b.path, t, [now[i].x, now[i].y], b.trailColour, {
          width: selected ? 2.4 : 1.6,
          alpha: selected ? 0.95 : 0.75,
        });
      });
    }
    this.drawFlashes(ctx, t);

    view.applyCss(ctx);
    const r = this.model.radius * view.scale;
    this.balls.forEach((b, i) => {
      const { ball } = b;
      if (!this.visible(ball, t)) return;
      let [x, y] = view.toCss(now[i].x, now[i].y);
      let radius = r;
      let alpha = 1;
      if (ball.pocketed && t >= ball.pocketTime) {
        // dropping into the pocket: towards its centre, smaller and fading
        const k = (t - ball.pocketTime) / POCKET_DROP_TIME;
        if (ball.pocket) {
          const [px, py] = view.toCss(ball.pocket.centre[0], ball.pocket.centre[1]);
          x += (px - x) * k;
          y += (py - y) * k;
        }
        radius = r * (1 - 0.4 * k);
        alpha = 1 - k;
      }
      drawBall(ctx, b.style, x, y, radius, { alpha, selected: b === this.selected });
    });
  }

  // Where and when the contacts happen, to mark them briefly on the table.
  contactFlashes() {
    const out = [];
    for (const e of this.model.events) {
      if (TRANSITION_EVENTS.has(e.type) || e.type === 'cue_strike') continue;
      const balls = e.balls.map((id) => this.model.byId.get(id)).filter(Boolean);
      if (balls.length === 0) continue;
      const states = balls.map((b) => stateAt(this.model, b, e.time));
      const x = states.reduce((sum, s) => sum + s.x, 0) / states.length;
      const y = states.reduce((sum, s) => sum + s.y, 0) / states.length;
      out.push({ time: e.time, x, y, type: e.type });
    }
    return out;
  }

  drawFlashes(ctx, t) {
    const view = this.view;
    view.applyTable(ctx);
    ctx.save();
    ctx.lineWidth = view.metres(2);
    for (const f of this.flashes) {
      const age = t - f.time;
      if (age < 0 || age > FLASH_TIME) continue;
      const k = age / FLASH_TIME;
      ctx.globalAlpha = 0.9 * (1 - k);
      ctx.strokeStyle = f.type === 'ball_ball' ? '#ffb23f' : f.type === 'ball_pocket' ? '#ff5a5a' : '#4fd1e8';
      ctx.beginPath();
      ctx.arc(f.x, f.y, this.model.radius * (1.3 + 0.8 * k), 0, 2 * Math.PI);
      ctx.stroke();
    }
    ctx.restore();
  }

  renderSelected(t) {
    const entry = this.selected;
    if (!entry) {
      this.el.readout.textContent = '';
      this.plot.draw(t, null);
      return;
    }
    const { ball } = entry;
    const s = stateAt(this.model, ball, t);
    const phase = phaseAt(this.model, ball, t);
    const v = phase === 'pocketed' ? 0 : speed(s);
    const w = phase === 'pocketed' ? 0 : angularSpeed(s);
    const el = this.el.readout;
    el.replaceChildren();
    const title = document.createElement('b');
    title.textContent = `${ball.name} · ${phase}`;
    el.append(
      title,
      `\n|v| = ${v.toFixed(3)} m/s · |ω| = ${w.toFixed(1)} rad/s`,
      phase === 'pocketed'
        ? `\nin the ${ball.pocketName} pocket at ${ball.pocketTime.toFixed(3)} s`
        : `\nω = (${s.wx.toFixed(1)}, ${s.wy.toFixed(1)}, ${s.wz.toFixed(1)}) rad/s\nat (${s.x.toFixed(3)}, ${s.y.toFixed(3)}) m`,
    );
    this.plot.draw(t, { v, w });
  }
}

function last(list) {
  return list.length > 0 ? list[list.length - 1] : null;
}
