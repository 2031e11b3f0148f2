// The fragments of one mesh, seed and count as each fracturer made them, side by side in 3D: orbit and
// zoom each view, one explode slider for the row, the cut faces in their interior material and the
// surface in the mesh's own materials and textures, a fragment's volume on hover. Answers "what do
// voronoi's fragments look like beside plane-slice's?". The fragments come from the folders' own
// fragments.glb (docs/results.md, "Fragments folder"), embedded in the page.

import * as THREE from "three";
import { GLTFLoader } from "three/examples/jsm/loaders/GLTFLoader.js";
import { unpack } from "./inflate.js";
import { baseName, el, formatMs, formatNumber } from "./dom.js";
import { noWebglNote, View3D, webglAvailable } from "./scene3d.js";

const VIEW_WIDTH = 290;
const VIEW_HEIGHT = 290;
const FRAGMENT_NAME = /^fragment_\d+$/;

/** The fragments entries grouped by mesh, seed and requested count, in first-seen order. */
export function fragmentGroups(entries) {
  const groups = new Map();
  for (const e of entries) {
    const key = JSON.stringify([e.mesh, e.seed, e.requested]);
    if (!groups.has(key)) groups.set(key, { mesh: e.mesh, seed: e.seed, requested: e.requested, entries: [] });
    groups.get(key).entries.push(e);
  }
  return [...groups.values()];
}

/** Parses the glTF binary of `entry`; its images named by URI come from the entry's data: URLs. */
async function loadFragments(entry) {
  const manager = new THREE.LoadingManager();
  const images = entry.images || {};
  manager.setURLModifier((url) => (Object.prototype.hasOwnProperty.call(images, url) ? images[url] : url));
  const bytes = await unpack(entry.glb);
  return new Promise((resolve, reject) => new GLTFLoader(manager).parse(bytes.buffer, "", resolve, reject));
}

/** The fragment nodes of a loaded scene: name, object, volume (node extras) and rest position. */
function fragmentNodes(root) {
  const out = [];
  root.traverse((o) => {
    if (!FRAGMENT_NAME.test(o.name) || out.some((n) => n.object === o)) return;
    let meshes = 0;
    o.traverse((m) => {
      if (m.isMesh) {
        meshes += 1;
        m.material = m.material.clone();  // its own, so a hover can light one fragment
      }
    });
    const volume = o.userData && Number.isFinite(o.userData.volume) ? o.userData.volume : NaN;
    out.push({ name: o.name, object: o, meshes, volume, rest: o.position.clone() });
  });
  return out;
}

/** One fracturer's view: label, canvas, hover line; `explode(k)` spreads the fragments by k. */
function fragmentsPanel(entry) {
  const summary = entry.summary || {};
  const time = Number.isFinite(summary.time_ms) ? `, ${formatMs(summary.time_ms)}` : "";
  const panel = el("figure", { class: "fragments-panel", "data-view": "fragments", "data-algorithm": entry.algorithm, "data-fragments": entry.fragments, title: entry.folder },
    el("figcaption", { class: "chart-title" }, `${entry.algorithm}: ${entry.fragments} fragments${time}`));
  const hover = el("p", { class: "hover-line", "data-hover": "" }, "Hover a fragment for its volume.");
  let nodes = [];
  let centre = new THREE.Vector3();
  let distance = 1;  // the camera's distance from the target with the fragments at rest
  let view = null;
  let lit = null;
  const light = (node) => {
    if (lit === node) return;
    for (const n of [lit, node]) {
      if (!n) continue;
      n.object.traverse((m) => { if (m.isMesh && m.material.emissive) m.material.emissive.setHex(n === node ? 0x5c3b00 : 0x000000); });
    }
    lit = node;
  };
  return {
    element: panel,
    async mount(onLoaded) {
      if (!webglAvailable()) { panel.append(noWebglNote()); return; }
      view = new View3D(VIEW_WIDTH, VIEW_HEIGHT);
      panel.append(view.canvas, hover);
      let gltf;
      try {
        gltf = await loadFragments(entry);
      } catch (error) {
        panel.append(el("p", { class: "error" }, `${baseName(entry.folder)}: the fragments could not be read: ${error && error.message ? error.message : error}`));
        console.error(error);
        return;
      }
      view.scene.add(gltf.scene);
      nodes = fragmentNodes(gltf.scene);
      const total = nodes.reduce((s, n) => s + (Number.isFinite(n.volume) ? n.volume : 0), 0);
      // The centre the row explodes from: the volume-weighted centroid of the fragments.
      centre = nodes.reduce((c, n) => c.addScaledVector(n.rest, Number.isFinite(n.volume) ? n.volume : 0), new THREE.Vector3())
        .multiplyScalar(total > 0 ? 1 / total : 0);
      const sphere = new THREE.Box3().setFromObject(gltf.scene).getBoundingSphere(new THREE.Sphere());
      view.frame(sphere.center, sphere.radius);
      distance = view.camera.position.distanceTo(view.controls.target);
      panel.dataset.meshes = String(nodes.filter((n) => n.meshes > 0).length);
      panel.dataset.totalVolume = String(total);
      view.canvas.addEventListener("pointermove", (event) => {
        const hit = view.pick(event, nodes.map((n) => n.object))[0];
        const node = hit ? nodes.find((n) => { let o = hit.object; while (o && o !== n.object) o = o.parent; return o === n.object; }) : null;
        light(node);
        hover.textContent = node
          ? `${node.name}: volume ${formatNumber(node.volume)} m³ (${formatNumber((100 * node.volume) / total)} % of the whole)`
          : "Hover a fragment for its volume.";
        hover.dataset.hover = node ? node.name : "";
        view.draw();
      });
      view.canvas.addEventListener("pointerleave", () => { light(null); view.draw(); });
      view.draw();
      panel.dataset.ready = "true";
      if (onLoaded) onLoaded();
    },
    explode(k) {
      for (const n of nodes) n.object.position.copy(n.rest).addScaledVector(n.rest.clone().sub(centre), k);
      if (!view) return;
      // The camera backs away as the fragments spread, so the outer ones stay in view.
      const offset = view.camera.position.clone().sub(view.controls.target);
      view.camera.position.copy(view.controls.target).addScaledVector(offset.normalize(), distance * (1 + 0.4 * k));
      view.controls.update();
      view.draw();
    },
  };
}

/** One section per group: its fracturers side by side and the row's explode slider. */
export function fragmentsSection(group) {
  const section = el("section", { class: "file-section", "data-section": "fragments" },
    el("h2", {}, `Fragments: ${group.mesh}, seed ${group.seed}, ${group.requested} requested`),
    el("p", { class: "note" }, "Each fracturer's fragments of the same mesh and seed. Drag to orbit, scroll to zoom; "
      + "cut faces are drawn in the interior material, the surface in the mesh's own. Sources: "
      + group.entries.map((e) => baseName(e.folder)).join(", ") + "."));
  const slider = el("input", { type: "range", min: 0, max: 100, value: 0, "data-control": "explode", "aria-label": "explode" });
  const readout = el("span", { class: "readout" }, "0 %");
  section.append(el("label", { class: "explode" }, "Explode ", slider, " ", readout));
  const panels = group.entries.map(fragmentsPanel);
  section.append(el("div", { class: "fragments-row" }, panels.map((p) => p.element)));
  slider.addEventListener("input", () => {
    readout.textContent = `${slider.value} %`;
    for (const p of panels) p.explode(Number(slider.value) / 100);
  });
  return {
    element: section,
    mount() {
      return Promise.all(panels.map((p) => p.mount())).then(() => { section.dataset.ready = "true"; });
    },
  };
}
