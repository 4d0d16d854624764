// The page of a porosity result: the bed in 3D (one InstancedMesh per particle shape, so 1e5
// particles are a handful of draw calls), a height clip slider, the container, and the profile
// plots (radial with the correlation, bins, axial, the r-z map as a heat map) (docs/viewer.md).
import * as THREE from 'three';
import { colormap, cssColor } from './colors.js';
import { Plot } from './plot2d.js';
import { checkbox, el, fmt } from './dom.js';
import { sphereSprites } from './sphere_sprites.js';

const SPRITES_ABOVE = 20000;  // spheres; above this many they are drawn as point sprites

export function porosityView(data, viewport, side, toolbar) {
  const P = data.particles, n = P.count, R = data.container.radius, [z0, z1] = data.container.z_range;
  let zmin = Infinity, zmax = -Infinity;
  for (let k = 0; k < n; ++k) { zmin = Math.min(zmin, P.centre[3 * k + 2]); zmax = Math.max(zmax, P.centre[3 * k + 2]); }
  if (n === 0) { zmin = z0; zmax = z1; }
  let dmax = 0;
  for (let k = 0; k < n; ++k) dmax = Math.max(dmax, P.diameter[k]);
  if (n === 0) dmax = 1;
  const clip = new THREE.Plane(new THREE.Vector3(0, 0, -1), zmax + dmax);  // keeps z <= constant
  // Large sphere beds as point sprites: 1e5 spheres as triangles are 8e6 triangles, too many for
  // software WebGL (headless Chromium) to turn at interactive rates.
  const heightColour = (z) => colormap(0.15 + (0.7 * (z - zmin)) / Math.max(1e-12, zmax - zmin));
  const sprites = !P.length && n > SPRITES_ABOVE;
  const meshes = sprites ? [sphereSprites(P.centre, P.diameter, (k) => heightColour(P.centre[3 * k + 2]), viewport)]
    : buildBed(P, n, clip, heightColour);
  meshes.forEach((m) => viewport.scene.add(m));
  // The container: a translucent cylinder of radius R over the profile's height range.
  const wall = new THREE.Mesh(new THREE.CylinderGeometry(R, R, z1 - z0, 96, 1, true).rotateX(Math.PI / 2).translate(0, 0, (z0 + z1) / 2),
    new THREE.MeshPhongMaterial({ color: 0x8899aa, transparent: true, opacity: 0.15, side: THREE.DoubleSide, depthWrite: false }));
  viewport.scene.add(wall);

  const slider = el('input', { type: 'range', min: 0, max: 1000, value: 1000, title: 'clip the bed above this height' });
  const sliderText = el('span', { textContent: '' });
  slider.addEventListener('input', () => {
    const h = zmin - dmax + (zmax - zmin + 2 * dmax) * (slider.value / 1000);
    clip.constant = h;
    if (sprites) meshes[0].setClip(h);
    sliderText.textContent = ` z ≤ ${fmt(h, 4)}`;
    viewport.requestRender();
  });
  toolbar.append(el('label', {}, [document.createTextNode('clip '), slider, sliderText]));

  side.append(el('h2', { textContent: data.title || 'porosity' }),
    el('div', { className: 'legend', textContent: `${n} ${data.spherocylinders ? 'spherocylinders' : 'spheres'}, container radius ${fmt(R)}, ` +
      `heights ${fmt(z0)}…${fmt(z1)}, bulk porosity ${fmt(data.bulk_porosity, 6)}` }),
    checkbox('container wall', true, (on) => { wall.visible = on; viewport.requestRender(); }),
    checkbox('particles', true, (on) => { meshes.forEach((m) => (m.visible = on)); viewport.requestRender(); }));
  const plots = profilePlots(data, side);

  const box = new THREE.Box3(new THREE.Vector3(-R, -R, Math.min(z0, zmin)), new THREE.Vector3(R, R, Math.max(z1, zmax)));
  viewport.frame(box);
  return { counts: { meshes: meshes.length, particles: meshes.reduce((s, m) => s + m.count, 0), plots, sprites } };
}

// One InstancedMesh per shape (spheres; capsules of one length/diameter ratio), unit diameter scaled.
function buildBed(P, n, clip, heightColour) {
  const detail = n > SPRITES_ABOVE ? 1 : 2;
  const groups = new Map();  // length/diameter ratio (2 decimals) -> particle indices
  for (let k = 0; k < n; ++k) {
    const ratio = P.length ? Math.round((100 * P.length[k]) / P.diameter[k]) / 100 : 0;
    if (!groups.has(ratio)) groups.set(ratio, []);
    groups.get(ratio).push(k);
  }
  const meshes = [];
  const m = new THREE.Matrix4(), q = new THREE.Quaternion(), s = new THREE.Vector3(), c = new THREE.Vector3(), up = new THREE.Vector3(0, 1, 0);
  const colour = new THREE.Color();
  for (const [ratio, idx] of groups) {
    // Unit diameter; a capsule of length `ratio` along y (CapsuleGeometry's axis), scaled by d.
    const g = ratio === 0 ? new THREE.IcosahedronGeometry(0.5, detail) : new THREE.CapsuleGeometry(0.5, ratio, 3 * detail, 6 * detail);
    const mat = new THREE.MeshLambertMaterial({ clippingPlanes: [clip] });
    const mesh = new THREE.InstancedMesh(g, mat, idx.length);
    idx.forEach((k, j) => {
      c.set(P.centre[3 * k], P.centre[3 * k + 1], P.centre[3 * k + 2]);
      if (P.axis) q.setFromUnitVectors(up, new THREE.Vector3(P.axis[3 * k], P.axis[3 * k + 1], P.axis[3 * k + 2]).normalize());
      else q.identity();
      s.setScalar(P.diameter[k]);
      mesh.setMatrixAt(j, m.compose(c, q, s));
      // Colour by height, so that layers read in the picture.
      mesh.setColorAt(j, colour.setRGB(...heightColour(c.z)));
    });
    mesh.instanceMatrix.needsUpdate = true;
    mesh.computeBoundingSphere();
    meshes.push(mesh);
  }
  return meshes;
}

function range(values, pad = 0.02) {
  let lo = Infinity, hi = -Infinity;
  for (const v of values) if (Number.isFinite(v)) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
  const d = (hi - lo) * pad || 0.05;
  return [lo - d, hi + d];
}

function profilePlots(data, side) {
  let count = 0;
  const canvas = () => { count += 1; return el('canvas', { className: 'plot' }); };
  if (data.radial) {
    side.append(el('h3', { textContent: 'Radial profile ε(r)' }));
    const cv = canvas(), r = data.radial, corr = data.correlation;
    const ys = [...r.porosity, ...(corr ? corr.porosity : []), ...(data.bins ? data.bins.porosity : [])];
    const p = new Plot(cv, [0, data.container.radius], range([0, 1, ...ys].filter((v) => v <= 1 && v >= 0)), 'r', 'porosity');
    p.axes();
    if (data.bins) p.line(data.bins.x.flatMap((x, k) => [[x, data.bins.porosity[k]], [data.bins.x_upper[k], data.bins.porosity[k]]]), '#aaa', { width: 1.2 });
    p.line(r.x.map((x, k) => [x, r.porosity[k]]), '#1f77b4');
    if (corr) p.line(corr.x.map((x, k) => [x, corr.porosity[k]]), '#d62728', { dashed: true });
    p.legend([['exact (ssimarch)', '#1f77b4'], ...(corr ? [[`de Klerk (2003), ε_b = ${fmt(corr.eps_b, 4)}`, '#d62728', true]] : []),
      ...(data.bins ? [['annular bins', '#aaa']] : [])]);
    side.append(cv);
  }
  if (data.axial) {
    side.append(el('h3', { textContent: 'Axial profile ε(z)' }));
    const cv = canvas(), a = data.axial;
    const p = new Plot(cv, range(a.x, 0), range(a.porosity), 'z', 'porosity');
    p.axes();
    p.line(a.x.map((x, k) => [x, a.porosity[k]]), '#2ca02c');
    side.append(cv);
  }
  if (data.map) {
    side.append(el('h3', { textContent: 'Map ε(r, z)' }));
    const cv = canvas(), m = data.map, [lo, hi] = range(m.porosity, 0);
    const half = (a) => (a.length > 1 ? (a[1] - a[0]) / 2 : 0.5);
    const p = new Plot(cv, [m.r[0] - half(m.r), m.r[m.r.length - 1] + half(m.r)], [m.z[0] - half(m.z), m.z[m.z.length - 1] + half(m.z)], 'r', 'z', 1.1);
    p.axes();
    p.heatmap(m.r, m.z, m.porosity, lo, hi);
    side.append(cv, el('div', { className: 'legend' }, [
      document.createTextNode(`porosity ${fmt(lo, 3)} `),
      el('span', { className: 'swatch', style: `width:120px;background:linear-gradient(90deg,${[0, 0.25, 0.5, 0.75, 1].map((s) => cssColor(colormap(s))).join(',')})` }),
      document.createTextNode(` ${fmt(hi, 3)}`)]));
  }
  return count;
}
