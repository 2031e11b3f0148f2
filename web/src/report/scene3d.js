// What the 3D views share: one WebGL renderer for the whole page, drawing each view's scene and copying
// the picture into the view's own 2D canvas, so a page with many views holds one GL context (browsers
// allow a handful), and each view's camera, orbit controls and lights.

import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";
import { el } from "./dom.js";

export const BACKGROUND = 0xf1f3f5;
let shared = null;  // { renderer } or { error }

/** The page's renderer, made on first use; null when the browser has no WebGL. */
function renderer() {
  if (shared) return shared.renderer || null;
  try {
    const r = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    r.setPixelRatio(1);
    r.setClearColor(BACKGROUND, 1);
    shared = { renderer: r };
  } catch (error) {
    shared = { error };
    console.warn(`3D views: no WebGL (${error && error.message ? error.message : error})`);
  }
  return shared.renderer || null;
}

/** True when the page can draw 3D views. */
export function webglAvailable() {
  return renderer() !== null;
}

/**
 * One 3D view: a canvas of `width` x `height` px with its scene, camera (up along `up`) and orbit
 * controls; `draw()` renders it (on demand: after a change, not every animation frame).
 */
export class View3D {
  constructor(width, height, up = new THREE.Vector3(0, 1, 0)) {
    this.width = width;
    this.height = height;
    this.canvas = el("canvas", { class: "view3d", width, height });
    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(40, width / height, 0.01, 1000);
    this.camera.up.copy(up);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x5c5f66, 1.6));
    const key = new THREE.DirectionalLight(0xffffff, 1.8);
    key.position.set(0.4, 1, 0.6);
    this.camera.add(key);  // the light follows the camera, so the side in view is lit
    this.scene.add(this.camera);
    this.controls = new OrbitControls(this.camera, this.canvas);
    this.controls.addEventListener("change", () => this.draw());
    this.drawn = 0;
  }

  /** Puts the camera so that the sphere (`center`, `radius`) fills the view, looking from `direction`. */
  frame(center, radius, direction = new THREE.Vector3(1, 0.8, 1.4)) {
    const r = Math.max(radius, 1e-6);
    const distance = r / Math.sin(THREE.MathUtils.degToRad(this.camera.fov / 2)) * 1.05;
    this.camera.near = distance / 100;
    this.camera.far = distance * 100;
    this.camera.position.copy(center).addScaledVector(direction.clone().normalize(), distance);
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(center);
    this.controls.update();
  }

  /** Renders the scene into this view's canvas. */
  draw() {
    const r = renderer();
    if (!r) return;
    // The shared drawing buffer only grows (resizing it is costly); a view renders into its lower-left
    // corner, which is the bottom of the buffer's canvas.
    const size = r.getSize(new THREE.Vector2());
    if (size.x < this.width || size.y < this.height) r.setSize(Math.max(size.x, this.width), Math.max(size.y, this.height), false);
    const height = r.getSize(new THREE.Vector2()).y;
    r.setViewport(0, 0, this.width, this.height);
    r.setScissor(0, 0, this.width, this.height);
    r.setScissorTest(true);
    r.render(this.scene, this.camera);
    const ctx = this.canvas.getContext("2d");
    ctx.drawImage(r.domElement, 0, height - this.height, this.width, this.height, 0, 0, this.width, this.height);
    this.drawn += 1;
    this.canvas.dataset.drawn = String(this.drawn);
  }

  /** The scene objects under the pointer event `event`, nearest first. */
  pick(event, objects) {
    const box = this.canvas.getBoundingClientRect();
    const pointer = new THREE.Vector2(((event.clientX - box.left) / box.width) * 2 - 1, -((event.clientY - box.top) / box.height) * 2 + 1);
    const ray = new THREE.Raycaster();
    ray.setFromCamera(pointer, this.camera);
    return ray.intersectObjects(objects, true);
  }
}

/** A note in place of a 3D view when the browser cannot draw one. */
export function noWebglNote() {
  return el("p", { class: "note", "data-webgl": "none" }, "This browser has no WebGL: the 3D view cannot be drawn.");
}
