// The studio's 3D scenes (three.js), shared by the folded view and the editors: a renderer in
// a container, ambient and sun light on a light grey background, a camera, and the model in a
// group that a drag turns.
import * as THREE from './vendor/three.module.min.js';

/**
 * A renderer appended to `container`, a lit scene, a camera and an empty `model` group in the
 * scene. `sun` is the sun light's direction, `light` the [ambient, sun] intensities; `zUp`
 * puts the camera's up along z (cards stand on the x–y plane).
 */
export function makeScene(container, { sun = [1, 2, 3], light = [1.2, 2.0], zUp = false } = {}) {
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  container.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xeef1f5);
  scene.add(new THREE.AmbientLight(0xffffff, light[0]));
  const sunLight = new THREE.DirectionalLight(0xffffff, light[1]);
  sunLight.position.set(...sun);
  scene.add(sunLight);
  const camera = new THREE.PerspectiveCamera(35, 1, 0.1, 1e6);
  if (zUp) camera.up.set(0, 0, 1);
  const model = new THREE.Group();
  scene.add(model);
  return { renderer, scene, camera, model };
}

/** Calls `turn(dx, dy)` (pixels since the last call) while the pointer drags on `canvas`. */
export function onDrag(canvas, turn) {
  let drag = null;
  canvas.addEventListener('pointerdown', (e) => { drag = [e.clientX, e.clientY]; });
  canvas.addEventListener('pointermove', (e) => {
    if (!drag) return;
    turn(e.clientX - drag[0], e.clientY - drag[1]);
    drag = [e.clientX, e.clientY];
  });
  for (const end of ['pointerup', 'pointerleave']) canvas.addEventListener(end, () => { drag = null; });
}
