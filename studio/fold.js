// The folded form in 3D (three.js): frames of the bar-and-hinge simulation from flat to the
// settled fold, chosen with a slider (blended between computed frames). Drag turns the model.
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

  /** Shows the fold at `percent`: a computed frame when one is there, else a blend of the
   * two frames on either side (the static solve's frames are settled states a load step
   * apart). Returns what is shown: `{ percent, settled, blended }`. */
  showPercent(percent) {
    // By percentage; among frames at the same one the settled frame last, so it is found.
    const frames = [...this.fold.frames].sort((a, b) => a.percent - b.percent || a.settled - b.settled);
    const at = (p) => frames.filter((f) => f.percent === p).pop();
    const last = frames[frames.length - 1];
    if (percent >= last.percent) return this.showFrame(at(last.percent));
    if (percent <= frames[0].percent) return this.showFrame(at(frames[0].percent));
    const i = frames.findIndex((f) => f.percent >= percent);
    const [a, b] = [frames[i - 1], frames[i]];
    if (b.percent === percent) return this.showFrame(at(percent));
    const t = (percent - a.percent) / (b.percent - a.percent);
    const p = new Float32Array(a.positions.length);
    for (let k = 0; k < p.length; k += 1) p[k] = a.positions[k] + t * (b.positions[k] - a.positions[k]);
    this.setPositions(p);
    return { percent, settled: false, blended: true };
  }

  /** Shows one frame of the API's fold view (or a streamed one); returns it. */
  showFrame(frame) {
    this.setPositions(frame.positions);
    return frame;
  }

  setFrame(i) {
    return this.showFrame(this.fold.frames[i]);
  }

  /** Moves the sheet's vertices to `p` (x, y, z of every model vertex) and draws it. */
  setPositions(p) {
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
