// The 3D viewport: renderer, camera, orbit/pan/zoom controls, lights, render on demand, the reset
// and screenshot buttons and the orbit frame-rate probe used by the benchmark (docs/viewer.md).
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

export class Viewport {
  constructor(container, { antialias = true } = {}) {
    this.container = container;
    this.renderer = new THREE.WebGLRenderer({ antialias, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(Math.min(2, window.devicePixelRatio || 1));
    this.renderer.setClearColor(0xffffff, 1);
    this.renderer.localClippingEnabled = true;
    container.appendChild(this.renderer.domElement);
    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
    this.camera.up.set(0, 0, 1);  // z up, as in the scenes' boxes
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => this.requestRender());
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x888899, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.6);
    sun.position.set(1, 0.6, 1.4);
    this.camera.add(sun);  // the light turns with the view
    this.scene.add(this.camera);
    this.onRender = [];
    this.onResize = [];
    this.pending = false;
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  resize() {
    const w = Math.max(1, this.container.clientWidth), h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    for (const f of this.onResize) f(w, h);
    this.requestRender();
  }

  requestRender() {
    if (this.pending) return;
    this.pending = true;
    requestAnimationFrame(() => {
      this.pending = false;
      this.render();
    });
  }

  render() {
    this.renderer.render(this.scene, this.camera);
    for (const f of this.onRender) f();
  }

  // Frames the box (THREE.Box3) from a fixed oblique direction; the "reset view" state.
  frame(box) {
    this.home = box.clone();
    const c = box.getCenter(new THREE.Vector3()), r = Math.max(1e-9, box.getSize(new THREE.Vector3()).length() / 2);
    const d = r / Math.sin((this.camera.fov * Math.PI) / 360);
    this.camera.position.copy(c).add(new THREE.Vector3(1.0, -1.6, 0.9).normalize().multiplyScalar(d));
    this.camera.near = d / 200;
    this.camera.far = d * 20;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(c);
    this.controls.update();
    this.requestRender();
  }

  reset() {
    if (this.home) this.frame(this.home);
  }

  // Downloads the current view as a PNG.
  screenshot(name) {
    this.render();
    const a = document.createElement('a');
    a.href = this.renderer.domElement.toDataURL('image/png');
    a.download = `${name || 'ssimarch'}.png`;
    a.click();
  }

  // Turns the camera about the target by `degrees` over `frames` animation frames, rendering each;
  // resolves with frames per second (the benchmark's "frame rate while orbiting").
  measureOrbit(frames = 120, degrees = 360) {
    return new Promise((resolve) => {
      const target = this.controls.target.clone(), axis = this.camera.up.clone();
      const step = (degrees * Math.PI) / 180 / frames;
      let k = 0, t0 = 0;
      const tick = (t) => {
        if (k === 0) t0 = t;
        if (k === frames) {
          resolve({ frames, seconds: (t - t0) / 1000, fps: (1000 * frames) / (t - t0) });
          return;
        }
        const offset = this.camera.position.clone().sub(target).applyAxisAngle(axis, step);
        this.camera.position.copy(target).add(offset);
        this.camera.lookAt(target);
        this.render();
        this.renderer.getContext().finish();  // count the GPU's work, not only the submission
        k += 1;
        requestAnimationFrame(tick);
      };
      requestAnimationFrame(tick);
    });
  }
}
