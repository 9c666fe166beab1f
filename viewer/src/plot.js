// Speed and spin of the selected ball over time: |v| (m/s) and |w| (rad/s)
// against t, two strips sharing the time axis, with a cursor at the current
// time. Clicking the plot seeks to that time.

const MARGIN = { left: 44, right: 10, top: 8, bottom: 20 };
const GAP = 14; // px between the two strips

export class SpeedPlot {
  /**
   * @param {HTMLCanvasElement} canvas
   * @param {(t:number) => void} onSeek
   * @param {AbortSignal} [signal] removes the listener when aborted
   */
  constructor(canvas, duration, onSeek, signal = undefined) {
    this.canvas = canvas;
    this.duration = duration > 0 ? duration : 1;
    this.series = null;
    this.colour = '#fff';
    this.background = null; // cached curves, redrawn on resize or new series
    canvas.addEventListener('click', (e) => {
      const rect = canvas.getBoundingClientRect();
      const x = e.clientX - rect.left;
      const width = rect.width - MARGIN.left - MARGIN.right;
      onSeek(Math.min(1, Math.max(0, (x - MARGIN.left) / width)) * this.duration);
    }, { signal });
  }

  /** Shows a ball's series from speedSeries(). */
  setSeries(series, colour) {
    this.series = series;
    this.colour = colour;
    this.background = null;
  }

  resize() {
    this.background = null;
  }

  /**
   * Draws the curves and the cursor at time t, with dots at the current
   * values {v, w} (exact, from the closed forms).
   */
  draw(t, current) {
    const canvas = this.canvas;
    const dpr = window.devicePixelRatio || 1;
    const cssW = canvas.clientWidth;
    const cssH = canvas.clientHeight;
    if (cssW === 0 || cssH === 0) return;
    if (canvas.width !== Math.round(cssW * dpr) || canvas.height !== Math.round(cssH * dpr)) {
      canvas.width = Math.round(cssW * dpr);
      canvas.height = Math.round(cssH * dpr);
      this.background = null;
    }
    if (!this.background) this.background = this.drawCurves(cssW, cssH, dpr);
    const ctx = canvas.getContext('2d');
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    ctx.drawImage(this.background.image, 0, 0);
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);

    // cursor at the current time, with the current values
    const { strips, x } = this.background;
    const cx = x(t);
    ctx.strokeStyle = '#ffd84a';
    ctx.lineWidth = 1;
    ctx.beginPath();
    for (const s of strips) {
      ctx.moveTo(cx, s.top);
      ctx.lineTo(cx, s.bottom);
    }
    ctx.stroke();
    if (!this.series || !current) return;
    for (const s of strips) {
      ctx.beginPath();
      ctx.arc(cx, s.y(current[s.key]), 3, 0, 2 * Math.PI);
      ctx.fillStyle = '#ffd84a';
      ctx.fill();
    }
  }

  // Axes and curves into an offscreen canvas.
  drawCurves(cssW, cssH, dpr) {
    const image = document.createElement('canvas');
    image.width = Math.round(cssW * dpr);
    image.height = Math.round(cssH * dpr);
    const ctx = image.getContext('2d');
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    const x0 = MARGIN.left;
    const x1 = cssW - MARGIN.right;
    const x = (t) => x0 + ((x1 - x0) * t) / this.duration;
    const stripH = (cssH - MARGIN.top - MARGIN.bottom - GAP) / 2;
    const series = this.series || { t: [], v: [], w: [] };
    const strips = [
      { key: 'v', values: series.v, label: '|v| m/s', top: MARGIN.top },
      { key: 'w', values: series.w, label: '|ω| rad/s', top: MARGIN.top + stripH + GAP },
    ].map((s) => {
      const max = niceCeiling(Math.max(0, ...s.values));
      const bottom = s.top + stripH;
      return { ...s, bottom, max, y: (v) => bottom - (stripH * v) / max };
    });

    ctx.font = '10px system-ui, sans-serif';
    ctx.textBaseline = 'middle';
    for (const s of strips) {
      ctx.fillStyle = 'rgba(255, 255, 255, 0.04)';
      ctx.fillRect(x0, s.top, x1 - x0, s.bottom - s.top);
      ctx.strokeStyle = 'rgba(255, 255, 255, 0.25)';
      ctx.lineWidth = 1;
      ctx.beginPath();
      ctx.moveTo(x0 + 0.5, s.top);
      ctx.lineTo(x0 + 0.5, s.bottom + 0.5);
      ctx.lineTo(x1, s.bottom + 0.5);
      ctx.stroke();
      ctx.fillStyle = '#aab';
      ctx.textAlign = 'right';
      ctx.fillText(formatTick(s.max), x0 - 4, s.top + 4);
      ctx.fillText('0', x0 - 4, s.bottom);
      ctx.textAlign = 'right';
      ctx.fillStyle = '#dde';
      ctx.fillText(s.label, x1 - 4, s.top + 7);

      ctx.beginPath();
      s.values.forEach((v, i) => {
        const px = x(series.t[i]);
        const py = s.y(v);
        if (i === 0) ctx.moveTo(px, py);
        else ctx.lineTo(px, py);
      });
      ctx.strokeStyle = this.colour;
      ctx.lineWidth = 1.5;
      ctx.lineJoin = 'round';
      ctx.stroke();
    }
    // time axis
    ctx.fillStyle = '#aab';
    ctx.textBaseline = 'top';
    const step = niceStep(this.duration / 5);
    for (let t = 0; t <= this.duration + 1e-9; t += step) {
      if (t > 0 && x(t) > x1 - 34) break; // leave room for the unit
      ctx.textAlign = t === 0 ? 'left' : 'center';
      ctx.fillText(`${formatTick(t)}`, x(t), strips[1].bottom + 4);
    }
    ctx.textAlign = 'right';
    ctx.fillText('t, s', x1, strips[1].bottom + 4);
    return { image, strips, x };
  }
}

/** The smallest 1, 2 or 5 x 10^k at or above v (and 1 for v = 0). */
export function niceCeiling(v) {
  if (!(v > 0)) return 1;
  const e = Math.pow(10, Math.floor(Math.log10(v)));
  for (const m of [1, 2, 2.5, 5, 10]) if (m * e >= v * (1 - 1e-12)) return m * e;
  return 10 * e;
}

function niceStep(v) {
  if (!(v > 0)) return 1;
  const e = Math.pow(10, Math.floor(Math.log10(v)));
  for (const m of [1, 2, 5, 10]) if (m * e >= v) return m * e;
  return 10 * e;
}

function formatTick(v) {
  return Number(v.toPrecision(3)).toString();
}
