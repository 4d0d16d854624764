// The curves of one intersection in a surface's parameter plane (u, v): the domain rectangle,
// each curve in its colour (broken where a periodic parameter wraps), the picked point.
import { Plot } from './plot2d.js';
import { el } from './dom.js';

export class ParamPanel {
  // points: the singular and isolated points of the intersection (black dots, violet for isolated).
  constructor(plane, curves, points) {
    this.plane = plane;
    this.curves = curves;
    this.points = points;
    this.canvas = el('canvas', { className: 'plot' });
    let xr = plane.domain?.u, yr = plane.domain?.v;
    if (!xr || !yr) {  // no domain in the page: the curves' extent
      const us = curves.flatMap((c) => c.curve.points.map((p) => p.params[plane.iu]));
      const vs = curves.flatMap((c) => c.curve.points.map((p) => p.params[plane.iv]));
      xr = [Math.min(...us), Math.max(...us)];
      yr = [Math.min(...vs), Math.max(...vs)];
    }
    const pad = (r) => { const d = (r[1] - r[0]) * 0.03 || 1; return [r[0] - d, r[1] + d]; };
    this.domain = [xr, yr];
    this.plot = new Plot(this.canvas, pad(xr), pad(yr), plane.name + ': ' + (plane.iu === 0 ? 'u' : 'p'), plane.iu === 0 ? 'v' : 'q');
    this.picked = null;
    this.draw();
  }
  draw() {
    const p = this.plot, [xr, yr] = this.domain, { iu, iv } = this.plane;
    p.axes();
    p.line([[xr[0], yr[0]], [xr[1], yr[0]], [xr[1], yr[1]], [xr[0], yr[1]], [xr[0], yr[0]]], '#999', { dashed: true, width: 1 });
    for (const c of this.curves) {
      if (!c.line.visible) continue;
      const pts = [];
      let prev = null;
      for (const q of c.curve.points) {
        const a = [q.params[iu], q.params[iv]];
        // A jump of more than half the domain is a periodic wrap, not a piece of curve.
        if (prev && (Math.abs(a[0] - prev[0]) > (xr[1] - xr[0]) / 2 || Math.abs(a[1] - prev[1]) > (yr[1] - yr[0]) / 2)) pts.push(null);
        pts.push(a);
        prev = a;
      }
      p.line(pts, c.color, { width: 2 });
    }
    for (const q of this.points) p.dot(q.params[iu], q.params[iv], q.type === 'isolated' ? '#8e44ad' : '#000', 3);
    if (this.picked) {
      const q = this.picked.c.curve.points[this.picked.i];
      p.dot(q.params[iu], q.params[iv], '#000');
    }
  }
  mark(c, i) {
    this.picked = this.curves.includes(c) ? { c, i } : null;
    this.draw();
  }
}
