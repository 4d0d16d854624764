// The page of a trace result: the surfaces as semi-transparent meshes, the curves as thick
// polylines coloured by branch or by kappa / tau, markers at singular points, isolated points,
// open ends and start points, the parameter-plane panels and the point panel (docs/viewer.md).
import * as THREE from 'three';
import { Line2 } from 'three/addons/lines/Line2.js';
import { LineGeometry } from 'three/addons/lines/LineGeometry.js';
import { LineMaterial } from 'three/addons/lines/LineMaterial.js';
import { branchColor, colormap, robustRange, surfaceColors } from './colors.js';
import { ParamPanel } from './param_panel.js';
import { Labels } from './labels.js';
import { checkbox, el, fmt, vec } from './dom.js';

const LINE_WIDTH = 3;  // pixels
const PICK_RADIUS = 10;  // pixels

export function traceView(data, viewport, side, toolbar) {
  const intersections = data.intersections || [];
  const surfaces = data.surfaces || {};
  const bounds = new THREE.Box3();
  const surfaceMeshes = buildSurfaces(surfaces, viewport, bounds);
  const curves = [];  // {ix, ci, curve, run, line, geometry, color, visible}
  intersections.forEach((run, ix) => (run.curves || []).forEach((curve, ci) => {
    const pts = curve.points.map((p) => p.xyz);
    pts.forEach((p) => bounds.expandByPoint(vec(p)));
    curves.push({ ix, ci, run, curve, pts, color: branchColor(curves.length) });
  }));
  for (const run of intersections)
    for (const p of [...(run.singular_points || []), ...(run.isolated_points || [])]) bounds.expandByPoint(vec(p.xyz));
  if (bounds.isEmpty()) bounds.set(new THREE.Vector3(-1, -1, -1), new THREE.Vector3(1, 1, 1));
  const size = bounds.getSize(new THREE.Vector3()).length();

  // Curves and markers go in the transparent pass after the surfaces (which write no depth), so a
  // surface in front tints a curve without hiding it.
  const material = () => new LineMaterial({ color: 0xffffff, linewidth: LINE_WIDTH, vertexColors: true, worldUnits: false,
    transparent: true });
  for (const c of curves) {
    c.geometry = new LineGeometry();
    c.geometry.setPositions(c.pts.flat());
    c.line = new Line2(c.geometry, material());
    c.line.computeLineDistances();
    c.line.renderOrder = 2;
    viewport.scene.add(c.line);
  }
  viewport.onResize.push((w, h) => curves.forEach((c) => c.line.material.resolution.set(w, h)));
  viewport.resize();

  const labels = new Labels(viewport);
  const markers = buildMarkers(data, intersections, viewport, labels, size);

  // Colouring: by branch, or by kappa / tau through the colour map over their robust range.
  let mode = 'branch';
  const legend = el('div', { className: 'legend' });
  function recolour() {
    let range = null;
    if (mode !== 'branch') range = robustRange(curves.flatMap((c) => c.curve.points.map((p) => p[mode] ?? NaN)));
    for (const c of curves) {
      const rgb = c.curve.points.map((p) => mode === 'branch' ? new THREE.Color(c.color).toArray()
        : colormap(((p[mode] ?? NaN) - range[0]) / (range[1] - range[0])));
      c.geometry.setColors(rgb.flat());
    }
    legend.textContent = mode === 'branch' ? 'colour: one per curve (branch)'
      : `colour: ${mode === 'kappa' ? 'curvature κ' : 'torsion τ'} from ${fmt(range[0])} (violet) to ${fmt(range[1])} (yellow); grey: undetermined`;
    viewport.requestRender();
  }
  recolour();

  // Toolbar and side panel.
  const select = el('select', { title: 'colour the curves by' }, [
    el('option', { value: 'branch', textContent: 'colour: branch' }), el('option', { value: 'kappa', textContent: 'colour: κ' }),
    el('option', { value: 'tau', textContent: 'colour: τ' })]);
  select.addEventListener('change', () => { mode = select.value; recolour(); panels.forEach((p) => p.draw()); });
  toolbar.append(select);
  const info = el('div', { id: 'info', textContent: 'Hover over or click a curve.' });
  side.append(el('h2', { textContent: data.title || 'ssimarch' }), legend, el('h3', { textContent: 'Point' }), info);
  side.append(el('h3', { textContent: 'Surfaces' }));
  for (const [name, m] of Object.entries(surfaceMeshes))
    side.append(checkbox(`${name} (${surfaces[name].type === surfaces[name].form ? surfaces[name].form : `${surfaces[name].type}, ${surfaces[name].form}`})`, true, (on) => { m.visible = on; viewport.requestRender(); },
      surfaceColors[Object.keys(surfaceMeshes).indexOf(name) % surfaceColors.length]));
  if (Object.keys(surfaceMeshes).length === 0) side.append(el('div', { className: 'legend', textContent: 'no surface meshes (ssimarch view --scene SCENE adds them)' }));
  side.append(el('h3', { textContent: 'Curves' }));
  for (const c of curves)
    side.append(checkbox(`${c.run.name} #${c.ci}: ${c.curve.closed ? 'closed' : 'open'}, length ${fmt(c.curve.length)}`, true,
      (on) => { c.line.visible = on; viewport.requestRender(); panels.forEach((p) => p.draw()); }, c.color));
  side.append(checkbox('markers and labels', true, (on) => { markers.forEach((m) => (m.visible = on)); labels.show(on); viewport.requestRender(); }));
  const panels = [];
  intersections.forEach((run, ix) => {
    for (const plane of parameterPlanes(run, surfaces)) {
      side.append(el('h3', { textContent: `${run.name}: ${plane.label}` }));
      const points = [...(run.singular_points || []), ...(run.isolated_points || [])].filter((q) => q.params);
      const p = new ParamPanel(plane, curves.filter((c) => c.ix === ix), points);
      side.append(p.canvas);
      panels.push(p);
    }
  });

  // Picking: the curve point nearest the pointer on screen, within PICK_RADIUS pixels.
  const highlight = new THREE.Mesh(new THREE.SphereGeometry(size * 0.008, 16, 12), new THREE.MeshBasicMaterial({ color: 0x000000, transparent: true }));
  highlight.visible = false;
  highlight.renderOrder = 3;
  viewport.scene.add(highlight);
  let pinned = false;
  function nearest(x, y) {
    const v = new THREE.Vector3(), w = viewport.container.clientWidth, h = viewport.container.clientHeight;
    let best = null, bestD = PICK_RADIUS * PICK_RADIUS;
    for (const c of curves) {
      if (!c.line.visible) continue;
      c.pts.forEach((p, i) => {
        v.set(p[0], p[1], p[2]).project(viewport.camera);
        if (v.z > 1) return;
        const dx = (v.x + 1) * w / 2 - x, dy = (1 - v.y) * h / 2 - y, d = dx * dx + dy * dy;
        if (d < bestD) { bestD = d; best = { c, i }; }
      });
    }
    return best;
  }
  function show(hit) {
    if (!hit) return;
    const { c, i } = hit, p = c.curve.points[i], run = c.run;
    const unknowns = (run.unknowns || []).join(', ');
    info.textContent = [
      `${run.name} · curve ${c.ci} · point ${i} of ${c.curve.points.length}`,
      `xyz    ${p.xyz.map((x) => fmt(x, 7)).join(', ')}`,
      `params (${unknowns}) ${(p.params || []).map((x) => fmt(x, 7)).join(', ')}`,
      `t      ${p.t ? p.t.map((x) => fmt(x, 4)).join(', ') : '—'}`,
      `κ      ${p.kappa == null ? '—' : fmt(p.kappa, 6)}`,
      `τ      ${p.tau == null ? '—' : fmt(p.tau, 6)}`,
      `curve  ${c.curve.closed ? 'closed' : 'open'}, length ${fmt(c.curve.length, 10)}`,
    ].join('\n');
    highlight.position.copy(vec(p.xyz));
    highlight.visible = true;
    panels.forEach((pp) => pp.mark(c, i));
    viewport.requestRender();
  }
  const canvas = viewport.renderer.domElement;
  let down = null;
  canvas.addEventListener('pointerdown', (e) => { down = [e.offsetX, e.offsetY]; });
  canvas.addEventListener('pointerup', (e) => {
    if (!down || Math.hypot(e.offsetX - down[0], e.offsetY - down[1]) > 4) return;  // a drag, not a click
    const hit = nearest(e.offsetX, e.offsetY);
    pinned = !!hit;
    if (hit) show(hit);
  });
  let hoverQueued = false;
  canvas.addEventListener('pointermove', (e) => {
    if (pinned || e.buttons || hoverQueued) return;
    hoverQueued = true;
    requestAnimationFrame(() => { hoverQueued = false; show(nearest(e.offsetX, e.offsetY)); });
  });

  viewport.frame(bounds);
  return {
    counts: { meshes: Object.keys(surfaceMeshes).length, curves: curves.length, markers: markers.length, labels: labels.count() },
    // Page coordinates of a curve point (the browser test clicks there).
    screenPoint(k, i) {
      const p = vec(curves[k].pts[i]).project(viewport.camera), r = canvas.getBoundingClientRect();
      return { x: r.left + (p.x + 1) * r.width / 2, y: r.top + (1 - p.y) * r.height / 2 };
    },
    info: () => info.textContent,
  };
}

function buildSurfaces(surfaces, viewport, bounds) {
  const meshes = {};
  Object.entries(surfaces).forEach(([name, s], k) => {
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.Float32BufferAttribute(s.positions, 3));
    g.setIndex(s.triangles);
    g.computeVertexNormals();
    const m = new THREE.Mesh(g, new THREE.MeshPhongMaterial({
      color: surfaceColors[k % surfaceColors.length], transparent: true, opacity: 0.45, side: THREE.DoubleSide,
      depthWrite: false, shininess: 30 }));
    m.name = name;
    viewport.scene.add(m);
    g.computeBoundingBox();
    bounds.union(g.boundingBox);
    meshes[name] = m;
  });
  return meshes;
}

// Markers: singular points (black, labelled with their type), isolated points (violet), open
// curve ends (orange, labelled with the reason), given start points (green).
function buildMarkers(data, intersections, viewport, labels, size) {
  const markers = [];
  const sphere = new THREE.SphereGeometry(size * 0.011, 20, 14);
  const add = (xyz, color, label) => {
    const m = new THREE.Mesh(sphere, new THREE.MeshBasicMaterial({ color, transparent: true }));
    m.position.copy(vec(xyz));
    m.renderOrder = 3;
    viewport.scene.add(m);
    markers.push(m);
    if (label) labels.add(m.position, label);
  };
  for (const run of intersections) {
    for (const p of run.singular_points || []) add(p.xyz, 0x000000, `${p.type}${p.ak ? ' ' + p.ak : ''}`);
    for (const p of run.isolated_points || []) add(p.xyz, 0x8e44ad, `isolated point${p.ak ? ' ' + p.ak : ''}`);
    for (const c of run.curves || []) {
      if (c.closed || c.points.length === 0) continue;
      add(c.points[0].xyz, 0xff7f0e, `start end: ${c.ends?.start?.reason ?? '?'}`);
      add(c.points[c.points.length - 1].xyz, 0xff7f0e, `end: ${c.ends?.end?.reason ?? '?'}`);
    }
    for (const s of (data.starts || {})[run.name] || []) add(s, 0x2ca02c, 'start point');
  }
  return markers;
}

// The parameter planes with curves in them: the parametric surfaces of the pair, each with the
// indices of its two parameters in a point's params (docs/output-format.md).
function parameterPlanes(run, surfaces) {
  const first = run.parametric_first, other = (run.surfaces || []).find((s) => s !== first) ?? first;
  const plane = (name, iu, iv, names) => ({ name, iu, iv, label: `(${names}) plane of ${name}`,
    domain: surfaces[name]?.domain ?? null });
  if (run.pair_kind === 'parametric-parametric') return [plane(first, 0, 1, 'u, v'), plane(other, 2, 3, 'p, q')];
  if (run.pair_kind === 'parametric-implicit') return [plane(first, 0, 1, 'u, v')];
  return [];
}
