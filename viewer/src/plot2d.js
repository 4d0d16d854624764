// 2D plots on a canvas: axes with 1-2-5 ticks, polylines (solid or dashed), a heat map with its
// colour bar. Used by the parameter-plane panels and the porosity profiles.
import { colormap, cssColor } from './colors.js';
import { fmt } from './dom.js';

export function niceTicks(lo, hi, n = 5) {
  const span = hi - lo || 1, raw = span / n, p = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((m) => m * p).find((s) => s >= raw);
  const ticks = [];
  for (let t = Math.ceil(lo / step) * step; t <= hi + 1e-9 * span; t += step) ticks.push(Math.abs(t) < 1e-12 * span ? 0 : t);
  return ticks;
}

export class Plot {
  // canvas: the element; xr, yr: [lo, hi]; labels for the axes.
  constructor(canvas, xr, yr, xlabel, ylabel, aspect = 0.7) {
    const dpr = Math.min(2, window.devicePixelRatio || 1), w = 340;
    canvas.width = w * dpr;
    canvas.height = Math.round(w * aspect) * dpr;
    this.ctx = canvas.getContext('2d');
    this.ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    Object.assign(this, { w, h: Math.round(w * aspect), xr, yr, xlabel, ylabel, m: { l: 44, r: 10, t: 8, b: 32 } });
  }
  X(x) { const { l, r } = this.m; return l + ((x - this.xr[0]) / (this.xr[1] - this.xr[0])) * (this.w - l - r); }
  Y(y) { const { t, b } = this.m; return this.h - b - ((y - this.yr[0]) / (this.yr[1] - this.yr[0])) * (this.h - t - b); }
  axes() {
    const c = this.ctx, { l, r, t, b } = this.m;
    c.clearRect(0, 0, this.w, this.h);
    c.font = '10px system-ui, sans-serif';
    c.strokeStyle = '#e4e4e4';
    c.fillStyle = '#444';
    c.lineWidth = 1;
    for (const x of niceTicks(...this.xr)) {
      c.beginPath(); c.moveTo(this.X(x), t); c.lineTo(this.X(x), this.h - b); c.stroke();
      c.textAlign = 'center'; c.fillText(fmt(x, 3), this.X(x), this.h - b + 12);
    }
    for (const y of niceTicks(...this.yr)) {
      c.beginPath(); c.moveTo(l, this.Y(y)); c.lineTo(this.w - r, this.Y(y)); c.stroke();
      c.textAlign = 'right'; c.fillText(fmt(y, 3), l - 4, this.Y(y) + 3);
    }
    c.strokeStyle = '#888';
    c.strokeRect(l, t, this.w - l - r, this.h - t - b);
    c.textAlign = 'center';
    c.fillText(this.xlabel, (l + this.w - r) / 2, this.h - 4);
    c.save(); c.translate(10, (t + this.h - b) / 2);
    if (this.ylabel.length > 2) c.rotate(-Math.PI / 2);  // a one-letter label reads better upright
    c.fillText(this.ylabel, 0, 0); c.restore();
  }
  // points: [[x, y], ...]; a null entry breaks the line.
  line(points, color, { dashed = false, width = 1.6 } = {}) {
    const c = this.ctx;
    c.save();
    c.beginPath();
    c.rect(this.m.l, this.m.t, this.w - this.m.l - this.m.r, this.h - this.m.t - this.m.b);
    c.clip();
    c.strokeStyle = color;
    c.lineWidth = width;
    c.setLineDash(dashed ? [5, 4] : []);
    c.beginPath();
    let pen = false;
    for (const p of points) {
      if (!p) { pen = false; continue; }
      if (pen) c.lineTo(this.X(p[0]), this.Y(p[1])); else c.moveTo(this.X(p[0]), this.Y(p[1]));
      pen = true;
    }
    c.stroke();
    c.restore();
  }
  dot(x, y, color, r = 3.5) {
    const c = this.ctx;
    c.fillStyle = color;
    c.beginPath(); c.arc(this.X(x), this.Y(y), r, 0, 2 * Math.PI); c.fill();
  }
  legend(entries) {
    const c = this.ctx;
    c.font = '10px system-ui, sans-serif';
    c.textAlign = 'left';
    entries.forEach(([text, color, dashed], k) => {
      const y = this.m.t + 10 + 12 * k, x = this.m.l + 8;
      c.strokeStyle = color; c.lineWidth = 2; c.setLineDash(dashed ? [5, 4] : []);
      c.beginPath(); c.moveTo(x, y - 3); c.lineTo(x + 18, y - 3); c.stroke(); c.setLineDash([]);
      c.fillStyle = '#333'; c.fillText(text, x + 22, y);
    });
  }
  // Cells centred at xs[i], ys[j] with values v[j * xs.length + i] mapped over [lo, hi].
  heatmap(xs, ys, v, lo, hi) {
    const c = this.ctx, edges = (a, k) => [k === 0 ? a[0] - (a[1] - a[0]) / 2 : (a[k - 1] + a[k]) / 2,
      k === a.length - 1 ? a[k] + (a[k] - a[k - 1]) / 2 : (a[k] + a[k + 1]) / 2];
    for (let j = 0; j < ys.length; ++j)
      for (let i = 0; i < xs.length; ++i) {
        const [x0, x1] = edges(xs, i), [y0, y1] = edges(ys, j);
        c.fillStyle = cssColor(colormap((v[j * xs.length + i] - lo) / (hi - lo)));
        c.fillRect(this.X(x0), this.Y(y1), this.X(x1) - this.X(x0) + 0.5, this.Y(y0) - this.Y(y1) + 0.5);
      }
  }
}
