// Reads the recorded frames of `grid --record-frames` (the `OUT.frames.bin` sidecar, embedded in the
// page packed, inflate.js) into typed arrays the playback draws from. The layout is docs/results.md, "Recorded
// frames": little-endian, version 1, every plane aligned so that it is taken as a typed array view.
// The report writer has already checked the file whole; this reader still checks every offset
// against the length and throws on anything else, so a page never draws a half-read recording.

const MAGIC = "SBFRAMES";
const STAGES = ["prefracture", "bonds", "runtime_fracture", "bond_update", "stress", "falling_clusters", "colliders", "physics", "debris"];

/** Flag bits of a pose (recorded_frames.h). */
export const POSE_PRESENT = 1;
export const POSE_SPAWNED = 2;
export const POSE_TOUCHING_BODY = 4;
export const POSE_TOUCHING_GROUND = 8;

class Cursor {
  constructor(bytes, at, end) {
    this.view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    this.bytes = bytes;
    this.at = at;
    this.end = end;
  }
  need(n, what) {
    if (this.at + n > this.end) throw new Error(`recorded frames: ${what} runs past the end of its recording`);
  }
  u8() { this.need(1, "a byte"); return this.view.getUint8(this.at++); }
  i32() { this.need(4, "an integer"); const v = this.view.getInt32(this.at, true); this.at += 4; return v; }
  u32() { this.need(4, "a count"); const v = this.view.getUint32(this.at, true); this.at += 4; return v; }
  u64() { this.need(8, "a 64-bit value"); const v = this.view.getBigUint64(this.at, true); this.at += 8; return v; }
  f32() { this.need(4, "a float"); const v = this.view.getFloat32(this.at, true); this.at += 4; return v; }
  /** Moves to the next multiple of `n` from the start of the file. */
  pad(n) { const r = this.at % n; if (r) { this.need(n - r, "padding"); this.at += n - r; } }
  /** A copy of `count` values of a typed array kind (copied, so no alignment is assumed). */
  array(Kind, count, what) {
    const n = count * Kind.BYTES_PER_ELEMENT;
    this.need(n, what);
    const out = new Kind(count);
    new Uint8Array(out.buffer).set(this.bytes.subarray(this.at, this.at + n));
    this.at += n;
    return out;
  }
}

function readRecording(bytes, offset, size) {
  const c = new Cursor(bytes, offset, offset + size);
  const rec = { prefracture: c.i32(), runtime: c.i32(), repetition: c.i32() };
  const frames = c.u32();
  rec.seed = c.u64().toString();
  const meshCount = c.u32();
  const bodyCount = c.u32();
  const mask = c.u32();
  c.u32();
  rec.frames = frames;
  rec.frameMs = c.array(Float64Array, frames, "frame times");
  rec.stageMs = {};
  STAGES.forEach((name, s) => { if (mask & (1 << s)) rec.stageMs[name] = c.array(Float64Array, frames, `stage ${name}`); });
  rec.meshes = [];
  for (let m = 0; m < meshCount; m++) {
    const fragment = c.i32(), piece = c.i32(), vertices = c.u32(), triangles = c.u32();
    const origin = [c.f32(), c.f32(), c.f32()], step = [c.f32(), c.f32(), c.f32()];
    const q = c.array(Uint16Array, vertices * 3, "mesh vertices");
    c.pad(4);
    const index = vertices <= 65536 ? c.array(Uint16Array, triangles * 3, "triangles") : c.array(Uint32Array, triangles * 3, "triangles");
    c.pad(4);
    for (let i = 0; i < index.length; i++) if (index[i] >= vertices) throw new Error(`recorded frames: mesh ${m} has an index out of range`);
    const positions = new Float32Array(vertices * 3);
    for (let i = 0; i < vertices * 3; i++) positions[i] = origin[i % 3] + q[i] * step[i % 3];
    rec.meshes.push({ fragment, piece, positions, index });
  }
  rec.bodies = [];
  for (let b = 0; b < bodyCount; b++) {
    const kind = c.u8(); c.u8(); c.u8(); c.u8();
    const fragment = c.i32(), piece = c.i32();
    const restCentroid = [c.f32(), c.f32(), c.f32()];
    const count = c.u32();
    const meshes = Array.from(c.array(Uint32Array, count, "body meshes"));
    if (meshes.some((m) => m >= meshCount)) throw new Error(`recorded frames: body ${b} names a mesh out of range`);
    rec.bodies.push({ kind, fragment, piece, restCentroid, meshes });
  }
  c.pad(4);
  const poses = frames * bodyCount;
  rec.positions = c.array(Float32Array, poses * 3, "positions");
  const packed = c.array(Int16Array, poses * 3, "rotations");
  c.pad(4);
  rec.flags = c.array(Uint8Array, poses, "flags");
  const scales = c.array(Uint8Array, poses, "scales");
  rec.scales = new Float32Array(poses);
  for (let i = 0; i < poses; i++) rec.scales[i] = scales[i] / 255;
  rec.rotations = unpackRotations(packed, rec.flags, poses);
  return rec;
}

/** Quaternions (x, y, z, w) from the three smallest components and the dropped one's index in flags. */
function unpackRotations(packed, flags, poses) {
  const out = new Float32Array(poses * 4);
  const scale = 1 / (32767 * Math.SQRT2);
  for (let p = 0; p < poses; p++) {
    const dropped = (flags[p] >> 4) & 3;
    let sum = 0;
    let k = 0;
    for (let i = 0; i < 4; i++) {
      if (i === dropped) continue;
      const v = packed[p * 3 + k++] * scale;
      out[p * 4 + i] = v;
      sum += v * v;
    }
    out[p * 4 + dropped] = Math.sqrt(Math.max(0, 1 - sum));
  }
  return out;
}

/** Every recording of the sidecar bytes `bytes` (a Uint8Array), in file order. */
export function readRecordedFrames(bytes) {
  if (bytes.length < 16 || String.fromCharCode(...bytes.subarray(0, 8)) !== MAGIC) throw new Error("recorded frames: not a SBFRAMES file");
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const version = view.getUint32(8, true);
  if (version !== 1) throw new Error(`recorded frames: version ${version}, this page reads version 1`);
  const count = view.getUint32(12, true);
  if (16 + 16 * count > bytes.length) throw new Error("recorded frames: the table runs past the end");
  const out = [];
  for (let r = 0; r < count; r++) {
    const offset = Number(view.getBigUint64(16 + 16 * r, true));
    const size = Number(view.getBigUint64(24 + 16 * r, true));
    if (offset + size > bytes.length) throw new Error(`recorded frames: recording ${r} runs past the end`);
    out.push(readRecording(bytes, offset, size));
  }
  return out;
}
