// Entry point of the viewer bundle (docs/viewer.md): reads the page's inline data and builds the
// trace or porosity view. window.ssimarchViewer exposes counts and probes for the browser test and
// the benchmark (tests/browser, viewer/bench).
import { injectStyle } from './style.js';
import { Viewport } from './viewport.js';
import { traceView } from './trace_view.js';
import { porosityView } from './porosity_view.js';
import { el } from './dom.js';

function start() {
  injectStyle();
  const data = JSON.parse(document.getElementById('ssimarch-data').textContent);
  const view = el('div', { id: 'view' }), side = el('div', { id: 'side' }), toolbar = el('div', { id: 'toolbar' });
  document.body.append(el('div', { id: 'app' }, [view, side]));
  // Multisampling costs most in software WebGL; a large bed's sprites do without it.
  const viewport = new Viewport(view, { antialias: !(data.kind === 'porosity' && data.particles?.count > 20000) });
  view.append(toolbar, el('div', { id: 'title', textContent: `${data.title || ''} — drag: orbit, right-drag: pan, wheel: zoom` }));
  const reset = el('button', { textContent: 'reset view', title: 'back to the first view' });
  reset.addEventListener('click', () => viewport.reset());
  const shot = el('button', { textContent: 'screenshot', title: 'save the 3D view as PNG' });
  shot.addEventListener('click', () => viewport.screenshot(data.title));
  toolbar.append(reset, shot);
  const api = data.kind === 'porosity' ? porosityView(data, viewport, side, toolbar) : traceView(data, viewport, side, toolbar);
  viewport.render();
  window.ssimarchViewer = {
    ...api,
    kind: data.kind,
    ready: true,
    readyMs: performance.now(),
    measureOrbit: (frames, degrees) => viewport.measureOrbit(frames, degrees),
    render: () => viewport.render(),
  };
}

if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start);
else start();
