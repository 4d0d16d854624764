// Colours: a categorical palette for branches and surfaces, a perceptual map for kappa / tau / porosity.
import * as THREE from 'three';

// Tableau 10 (the matplotlib default cycle), readable on white.
const palette = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b', '#e377c2', '#17becf', '#bcbd22', '#7f7f7f'];
export const branchColor = (i) => palette[i % palette.length];
export const surfaceColors = ['#6fa8dc', '#f6b26b', '#93c47d', '#c27ba0'];

// Viridis at 9 stops, interpolated linearly (van der Walt & Smith, matplotlib 2.0).
const viridis = [[68, 1, 84], [71, 44, 122], [59, 81, 139], [44, 113, 142], [33, 144, 141], [39, 173, 129], [92, 200, 99],
  [170, 220, 50], [253, 231, 37]];
export function colormap(s) {
  if (!Number.isFinite(s)) return [0.6, 0.6, 0.6];
  const x = Math.min(1, Math.max(0, s)) * (viridis.length - 1);
  const i = Math.min(viridis.length - 2, Math.floor(x)), f = x - i;
  return viridis[i].map((c, k) => (c + f * (viridis[i + 1][k] - c)) / 255);
}
export const cssColor = (rgb) => `rgb(${rgb.map((c) => Math.round(255 * c)).join(',')})`;
export const threeColor = (css) => new THREE.Color(css);

// The 2nd and 98th percentiles of the finite values: near a singular point kappa blows up, and a
// range set by one point would paint the rest of the curve one colour.
export function robustRange(values) {
  const v = values.filter(Number.isFinite).sort((a, b) => a - b);
  if (v.length === 0) return [0, 1];
  const lo = v[Math.floor(0.02 * (v.length - 1))], hi = v[Math.ceil(0.98 * (v.length - 1))];
  return hi > lo ? [lo, hi] : [lo - 1, lo + 1];
}
