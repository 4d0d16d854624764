// Text labels pinned to 3D points: HTML elements over the canvas, moved after every render.
import * as THREE from 'three';

export class Labels {
  constructor(viewport) {
    this.viewport = viewport;
    this.items = [];
    this.visible = true;
    viewport.onRender.push(() => this.place());
  }
  add(position, text) {
    const div = document.createElement('div');
    div.className = 'label3d';
    div.textContent = text;
    this.viewport.container.appendChild(div);
    this.items.push({ position: position.clone(), div });
  }
  count() { return this.items.length; }
  show(on) { this.visible = on; this.place(); }
  place() {
    const v = new THREE.Vector3(), w = this.viewport.container.clientWidth, h = this.viewport.container.clientHeight;
    for (const { position, div } of this.items) {
      v.copy(position).project(this.viewport.camera);
      const on = this.visible && v.z < 1 && Math.abs(v.x) <= 1 && Math.abs(v.y) <= 1;
      div.style.display = on ? '' : 'none';
      if (on) {
        div.style.left = `${((v.x + 1) * w) / 2}px`;
        div.style.top = `${((1 - v.y) * h) / 2}px`;
      }
    }
  }
}
