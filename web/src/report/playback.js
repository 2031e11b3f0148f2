// The destruction event played back in 3D from the recording of a cell (`grid --record-frames`): every
// body where it was at the end of each frame, coloured by what it is and by what happened to it in
// that frame (entered the world, touching another body). A scrubber and a play button move through the
// frames; the cell's timeline moves with them and a click on the timeline jumps here. Answers "what
// happened in the frame that spiked?".

import * as THREE from "three";
import { el, formatMs } from "./dom.js";
import { POSE_PRESENT, POSE_SPAWNED, POSE_TOUCHING_BODY, POSE_TOUCHING_GROUND } from "./recorded_frames.js";
import { noWebglNote, View3D, webglAvailable } from "./scene3d.js";

const KIND_NAMES = ["fragment", "piece", "cluster"];
const KIND_COLOURS = [0x9aa5b1, 0xe8590c, 0x7048e8];
const SPAWNED_COLOUR = 0xfab005;
const TOUCHING_COLOUR = 0xe03131;
const FRAME_SECONDS = 1 / 60;  // the grid steps at 60 Hz

/** The up axis of a case: against gravity (`case.gravity`), else z (the built-in cases are z-up). */
function upAxis(caseDoc) {
  const g = caseDoc && Array.isArray(caseDoc.gravity) && caseDoc.gravity.length === 3 ? caseDoc.gravity : [0, 0, -9.81];
  const v = new THREE.Vector3(-g[0], -g[1], -g[2]);
  return v.lengthSq() > 0 ? v.normalize() : new THREE.Vector3(0, 0, 1);
}

function geometryOf(mesh) {
  const g = new THREE.BufferGeometry();
  g.setAttribute("position", new THREE.BufferAttribute(mesh.positions, 3));
  g.setIndex(new THREE.BufferAttribute(mesh.index, 1));
  g.computeVertexNormals();
  return g;
}

/** What to show in frame `f` of recording `rec`: counts of bodies present, spawned and touching. */
export function frameCounts(rec, f) {
  const B = rec.bodies.length;
  const counts = { present: 0, spawned: 0, touching: 0 };
  for (let b = 0; b < B; b++) {
    const flags = rec.flags[f * B + b];
    if (flags & POSE_PRESENT) counts.present += 1;
    if (flags & POSE_SPAWNED) counts.spawned += 1;
    if (flags & (POSE_TOUCHING_BODY | POSE_TOUCHING_GROUND)) counts.touching += 1;
  }
  return counts;
}

/**
 * The playback of `rec` (a recording of a cell of grid results `results`) in a new element;
 * `onFrame(f)` is called when the shown frame changes. `mount()` builds the scene; `show(f)` shows
 * frame f. The element carries `data-frame`, `data-frames`, `data-present`, `data-spawned`,
 * `data-touching` (of the shown frame, from the recording), `data-shown` (bodies drawn in the scene)
 * and `data-reached-end` once playing reached the last frame.
 */
export function playback(rec, results, onFrame) {
  const figure = el("figure", { class: "chart playback", "data-view": "playback", "data-frames": rec.frames, "data-bodies": rec.bodies.length,
    "data-cell": `${rec.prefracture} x ${rec.runtime}` },
    el("figcaption", { class: "chart-title" }, `Cell ${rec.prefracture} x ${rec.runtime}: the event played back (repetition ${rec.repetition + 1}, seed ${rec.seed})`),
    el("p", { class: "note" }, `${rec.bodies.length} bodies over ${rec.frames} frames. Grey: standing fragments; orange: runtime pieces; `
      + "purple: falling clusters; yellow: entered the world in this frame; red: touching another body or the ground. "
      + "Drag to orbit; click the timeline above to jump to a frame."));
  const scrubber = el("input", { type: "range", min: 0, max: Math.max(0, rec.frames - 1), value: 0, "data-control": "scrubber", "aria-label": "frame" });
  const play = el("button", { type: "button", "data-action": "play" }, "Play");
  const label = el("span", { class: "readout", "data-readout": "frame" }, "");
  figure.append(el("div", { class: "playback-controls" }, play, " ", scrubber, " ", label));
  const B = rec.bodies.length;
  let view = null;
  let bodies = [];
  let frame = -1;
  let playing = false;
  const materials = new Map();
  const material = (colour) => {
    if (!materials.has(colour)) materials.set(colour, new THREE.MeshStandardMaterial({ color: colour, roughness: 0.8, metalness: 0 }));
    return materials.get(colour);
  };

  const show = (f) => {
    f = Math.max(0, Math.min(rec.frames - 1, Math.round(f)));
    if (!view || f === frame) return;
    frame = f;
    for (let b = 0; b < B; b++) {
      const i = f * B + b;
      const flags = rec.flags[i];
      const body = bodies[b];
      body.visible = (flags & POSE_PRESENT) !== 0;
      body.position.fromArray(rec.positions, i * 3);
      body.quaternion.fromArray(rec.rotations, i * 4);
      body.scale.setScalar(Math.max(rec.scales[i], 1e-3));
      const colour = flags & POSE_SPAWNED ? SPAWNED_COLOUR
        : flags & (POSE_TOUCHING_BODY | POSE_TOUCHING_GROUND) && rec.bodies[b].kind !== 0 ? TOUCHING_COLOUR
          : KIND_COLOURS[rec.bodies[b].kind] ?? KIND_COLOURS[0];
      for (const child of body.children) child.material = material(colour);
    }
    const counts = frameCounts(rec, f);
    Object.assign(figure.dataset, { frame: String(f), present: String(counts.present), spawned: String(counts.spawned), touching: String(counts.touching),
      shown: String(bodies.filter((b) => b.visible).length) });
    const stages = Object.entries(rec.stageMs).filter(([, v]) => v[f] > 0).sort((a, b) => b[1][f] - a[1][f])
      .slice(0, 3).map(([name, v]) => `${name} ${formatMs(v[f])}`);
    label.textContent = `frame ${f}: ${formatMs(rec.frameMs[f])}${stages.length ? ` (${stages.join(", ")})` : ""}; `
      + `${counts.present} bodies, ${counts.spawned} entered, ${counts.touching} touching`;
    scrubber.value = String(f);
    view.draw();
    if (onFrame) onFrame(f);
  };

  const tick = (start, first) => (now) => {
    if (!playing) return;
    const f = first + Math.floor((now - start) / 1000 / FRAME_SECONDS);
    show(Math.min(f, rec.frames - 1));
    if (f >= rec.frames - 1) {
      playing = false;
      play.textContent = "Play";
      figure.dataset.reachedEnd = "true";
      return;
    }
    requestAnimationFrame(tick(start, first));
  };
  play.addEventListener("click", () => {
    playing = !playing;
    play.textContent = playing ? "Pause" : "Play";
    if (playing) {
      const first = frame >= rec.frames - 1 ? 0 : frame;
      const now = performance.now();
      requestAnimationFrame(tick(now, first));
    }
  });
  scrubber.addEventListener("input", () => { playing = false; play.textContent = "Play"; show(Number(scrubber.value)); });

  return {
    element: figure,
    show,
    mount(startFrame = 0) {
      if (!webglAvailable()) { figure.append(noWebglNote()); return; }
      view = new View3D(720, 420, upAxis(results && results.case));
      figure.append(view.canvas);
      const geometries = rec.meshes.map(geometryOf);
      const box = new THREE.Box3();
      for (const g of geometries) { g.computeBoundingBox(); box.union(g.boundingBox); }
      bodies = rec.bodies.map((b) => {
        const group = new THREE.Group();
        group.name = `body_${KIND_NAMES[b.kind] || "body"}`;
        for (const m of b.meshes) {
          const mesh = new THREE.Mesh(geometries[m], material(KIND_COLOURS[b.kind] ?? KIND_COLOURS[0]));
          mesh.position.set(-b.restCentroid[0], -b.restCentroid[1], -b.restCentroid[2]);
          group.add(mesh);
        }
        view.scene.add(group);
        return group;
      });
      const sphere = box.getBoundingSphere(new THREE.Sphere());
      const up = view.camera.up.clone();
      const ground = new THREE.GridHelper(sphere.radius * 6, 24, 0xadb5bd, 0xdee2e6);
      ground.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), up);
      ground.position.copy(sphere.center).addScaledVector(up, -sphere.center.dot(up));  // the plane through the origin
      view.scene.add(ground);
      const side = Math.abs(up.z) > 0.9 ? new THREE.Vector3(1.4, -1.2, 0) : new THREE.Vector3(1.4, 0, 1.2);
      view.frame(sphere.center, sphere.radius * 1.8, side.addScaledVector(up, 0.9));
      show(startFrame);
      figure.dataset.ready = "true";
    },
  };
}
