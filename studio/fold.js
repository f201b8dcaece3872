// The folded form in 3D (three.js): frames of the bar-and-hinge simulation from flat to the
// settled fold, chosen with a slider. Drag turns the model.
import * as THREE from './vendor/three.module.min.js';
import { makeScene, onDrag } from './scene3d.js';

/** Paper colours: the front (the pattern as drawn) and the back. */
const FRONT = 0xf4efe6;
const BACK = 0x6a8fd8;

export class FoldView {
  constructor(container) {
    this.container = container;
    Object.assign(this, makeScene(container));
    this.model.rotation.set(-0.9, 0, 0.5);
    onDrag(this.renderer.domElement, (dx, dy) => {
      this.model.rotation.z += dx * 0.01;
      this.model.rotation.x += dy * 0.01;
      this.draw();
    });
    new ResizeObserver(() => this.draw()).observe(container);
  }

  /** Takes the API's fold view (triangles and frames) and shows the flat sheet. */
  show(fold) {
    this.fold = fold;
    this.model.clear();
    const geometry = new THREE.BufferGeometry();
    geometry.setIndex(fold.triangles);
    geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(fold.frames[0].positions), 3));
    const front = new THREE.MeshLambertMaterial({ color: FRONT, side: THREE.FrontSide });
    const back = new THREE.MeshLambertMaterial({ color: BACK, side: THREE.BackSide });
    const edges = new THREE.LineSegments(new THREE.WireframeGeometry(geometry),
      new THREE.LineBasicMaterial({ color: 0x555555, transparent: true, opacity: 0.25 }));
    this.geometry = geometry;
    this.wire = edges;
    this.model.add(new THREE.Mesh(geometry, front), new THREE.Mesh(geometry, back), edges);
    // Centre the flat sheet and frame it.
    geometry.computeBoundingSphere();
    const { center, radius } = geometry.boundingSphere;
    this.model.position.set(0, 0, 0);
    this.centre = center.clone();
    this.radius = radius || 1;
    this.camera.position.set(0, 0, this.radius * 3.2);
    this.camera.near = this.radius * 0.01;
    this.camera.far = this.radius * 20;
    this.setFrame(0);
  }

  /** Shows the frame nearest to `percent`; returns it. */
  showPercent(percent) {
    const frames = this.fold.frames;
    let best = 0;
    frames.forEach((f, i) => {
      if (Math.abs(f.percent - percent) < Math.abs(frames[best].percent - percent)) best = i;
    });
    // Among frames at the same percentage prefer the settled one.
    const same = frames.findIndex((f) => f.settled && f.percent === frames[best].percent);
    return this.setFrame(same >= 0 ? same : best);
  }

  setFrame(i) {
    const frame = this.fold.frames[i];
    const p = frame.positions;
    const attr = this.geometry.getAttribute('position');
    for (let k = 0; k < p.length; k += 3) {
      attr.setXYZ(k / 3, p[k] - this.centre.x, p[k + 1] - this.centre.y, p[k + 2] - this.centre.z);
    }
    attr.needsUpdate = true;
    this.geometry.computeVertexNormals();
    this.model.remove(this.wire);
    this.wire.geometry.dispose();
    this.wire = new THREE.LineSegments(new THREE.WireframeGeometry(this.geometry), this.wire.material);
    this.model.add(this.wire);
    this.draw();
    return frame;
  }

  draw() {
    const w = this.container.clientWidth, h = this.container.clientHeight;
    if (!w || !h) return;
    this.renderer.setSize(w, h);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.renderer.render(this.scene, this.camera);
  }
}
