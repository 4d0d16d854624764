// Small DOM and number-format helpers.
import * as THREE from 'three';

export function el(tag, props = {}, children = []) {
  const e = document.createElement(tag);
  Object.assign(e, props);
  for (const c of children) e.append(c);
  return e;
}

export function checkbox(text, checked, onChange, swatch) {
  const box = el('input', { type: 'checkbox', checked });
  box.addEventListener('change', () => onChange(box.checked));
  const parts = [box];
  if (swatch) parts.push(el('span', { className: 'swatch', style: `background:${swatch}` }));
  parts.push(document.createTextNode(text));
  return el('label', { className: 'toggle', title: text }, parts);
}

export const vec = (p) => new THREE.Vector3(p[0], p[1], p[2]);

// Significant digits, without trailing zeros in the exponent-free range.
export function fmt(x, digits = 4) {
  if (x == null || !Number.isFinite(x)) return String(x);
  if (x !== 0 && (Math.abs(x) < 1e-4 || Math.abs(x) >= 1e6)) return x.toExponential(digits - 1);
  return String(Number(x.toPrecision(digits)));
}
