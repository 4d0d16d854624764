// Spheres as shaded point sprites ("impostors": one vertex per sphere, the disc shaded as a sphere
// in the fragment shader), for beds too large for triangle meshes in software WebGL (docs/viewer.md).
// The depth of a sprite is its centre's; the clip height hides whole spheres above it.
import * as THREE from 'three';

const vertexShader = `
attribute float diameter;
uniform float scale;
uniform float clipZ;
varying vec3 vColor;
varying float vClip;
void main() {
  vec4 mv = modelViewMatrix * vec4(position, 1.0);
  gl_Position = projectionMatrix * mv;
  gl_PointSize = diameter * scale / -mv.z;
  vColor = color;
  vClip = position.z - clipZ;
}`;

const fragmentShader = `
varying vec3 vColor;
varying float vClip;
void main() {
  if (vClip > 0.0) discard;
  vec2 p = gl_PointCoord * 2.0 - 1.0;
  p.y = -p.y;
  float r2 = dot(p, p);
  if (r2 > 1.0) discard;
  vec3 n = vec3(p, sqrt(1.0 - r2));
  vec3 l = normalize(vec3(0.4, 0.5, 0.8));
  float diffuse = max(dot(n, l), 0.0);
  float specular = pow(max(reflect(-l, n).z, 0.0), 24.0);
  gl_FragColor = vec4(vColor * (0.35 + 0.65 * diffuse) + 0.2 * specular, 1.0);
}`;

// centre: [x, y, z, ...], diameter: [...], colour(k) -> [r, g, b].
export function sphereSprites(centre, diameter, colour, viewport) {
  const n = diameter.length, g = new THREE.BufferGeometry();
  const rgb = new Float32Array(3 * n);
  for (let k = 0; k < n; ++k) rgb.set(colour(k), 3 * k);
  g.setAttribute('position', new THREE.Float32BufferAttribute(centre, 3));
  g.setAttribute('diameter', new THREE.Float32BufferAttribute(diameter, 1));
  g.setAttribute('color', new THREE.BufferAttribute(rgb, 3));
  const material = new THREE.ShaderMaterial({
    uniforms: { scale: { value: 1 }, clipZ: { value: Infinity } }, vertexShader, fragmentShader, vertexColors: true });
  const points = new THREE.Points(g, material);
  points.count = n;
  // Pixels per model length at unit distance: the drawing buffer's height over the view's height.
  const update = () => {
    const h = viewport.renderer.getDrawingBufferSize(new THREE.Vector2()).y;
    material.uniforms.scale.value = h / (2 * Math.tan((viewport.camera.fov * Math.PI) / 360));
  };
  viewport.onResize.push(update);
  update();
  points.setClip = (z) => { material.uniforms.clipZ.value = z; };
  return points;
}
