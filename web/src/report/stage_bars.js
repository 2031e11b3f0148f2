// Bars per stage: the worst frame's stage breakdown of a cell ("which stage made the hitch?"), and the
// stage totals of its runs when the worst frame's stages are not recorded.

import { el, formatMs } from "./dom.js";
import { stageColour } from "./timeline.js";

/**
 * The repetition whose slowest frame is the cell's worst frame: the median one by slowest frame (of an
 * even number the lower of the two middle ones, equal times in repetition order), or undefined.
 */
function medianSample(cell) {
  const samples = (cell.samples || []).filter((s) => Number.isFinite(s.worst_frame_ms));
  if (samples.length === 0) return undefined;
  const sorted = samples.map((s, k) => [s, k]).sort((a, b) => a[0].worst_frame_ms - b[0].worst_frame_ms || a[1] - b[1]);
  return sorted[Math.floor((sorted.length - 1) / 2)][0];
}

function stageObject(value) {
  if (!value || typeof value !== "object" || Array.isArray(value)) return undefined;
  const entries = Object.entries(value).filter(([, v]) => Number.isFinite(v));
  return entries.length > 0 ? entries : undefined;
}

/**
 * The worst frame's time per stage of `cell` as {stages: [[name, ms]...], frameMs, source}, or undefined
 * when the results do not record it. Read from, in order: the cell's `worst_frame_stages_ms`, the
 * median repetition's `worst_frame_stages_ms`, or that repetition's `frame_stages_ms` at its slowest
 * frame. `frameMs` is that frame's whole time (the median repetition's `worst_frame_ms`).
 */
export function worstFrameStages(cell) {
  const sample = medianSample(cell);
  const frameMs = sample ? sample.worst_frame_ms : undefined;
  const fromCell = stageObject(cell.worst_frame_stages_ms);
  if (fromCell) return { stages: fromCell, frameMs, source: "worst_frame_stages_ms of the cell" };
  if (!sample) return undefined;
  const fromSample = stageObject(sample.worst_frame_stages_ms);
  if (fromSample) return { stages: fromSample, frameMs, source: `worst_frame_stages_ms of the repetition with seed ${sample.seed}` };
  const perFrame = sample.frame_stages_ms;
  if (perFrame && typeof perFrame === "object" && Array.isArray(sample.frame_ms)) {
    let worst = 0;
    sample.frame_ms.forEach((v, i) => { if (v > sample.frame_ms[worst]) worst = i; });
    const stages = Object.entries(perFrame)
      .filter(([, v]) => Array.isArray(v) && Number.isFinite(v[worst]))
      .map(([name, v]) => [name, v[worst]]);
    if (stages.length > 0) return { stages, frameMs, source: `frame_stages_ms of the repetition with seed ${sample.seed}, frame ${worst}` };
  }
  return undefined;
}

/** The part of a frame of `frameMs` that no stage of `stages` timed (>= 0), or 0 when unknown. */
function outsideStages(stages, frameMs) {
  if (!Number.isFinite(frameMs)) return 0;
  return Math.max(0, frameMs - stages.reduce((sum, [, v]) => sum + v, 0));
}

/**
 * Horizontal bars, one per [name, ms] of `stages`, in a figure titled `title` that carries
 * `data-chart` = `kind` and `data-marks` = the number of bars.
 */
export function stageBars(kind, title, stages, note) {
  const max = Math.max(0, ...stages.map(([, v]) => v));
  const rows = stages.map(([name, ms]) =>
    el("div", { class: "bar-row", "data-stage": name, "data-value-ms": ms, title: `${name}: ${formatMs(ms)}` },
      el("span", { class: "bar-label" }, name),
      el("span", { class: "bar-track" },
        el("span", { class: "bar", style: `width: ${max > 0 ? ((100 * ms) / max).toFixed(2) : 0}%; background: ${stageColour(name)}` })),
      el("span", { class: "bar-value" }, formatMs(ms))));
  return el("figure", { class: "chart bars", "data-chart": kind, "data-marks": stages.length },
    el("figcaption", { class: "chart-title" }, title), note ? el("p", { class: "note" }, note) : null, el("div", { class: "bar-list" }, rows));
}

/** The stage views of one cell: its worst frame's breakdown, or a note and the stage totals. */
export function cellStageViews(cell) {
  const label = `${cell.prefracture} x ${cell.runtime}`;
  if (cell.failed !== undefined) return [];
  const worst = worstFrameStages(cell);
  const views = [];
  if (worst) {
    const outside = outsideStages(worst.stages, worst.frameMs);
    const note = Number.isFinite(worst.frameMs)
      ? `The worst frame took ${formatMs(worst.frameMs)}; its stages add up to ${formatMs(worst.frameMs - outside)}, and ${formatMs(outside)} went to no timed stage (work no stage timer covers, or the thread not running). From ${worst.source}.`
      : `From ${worst.source}.`;
    views.push(stageBars("worst-frame-stages", `Cell ${label}: the worst frame by stage`, worst.stages, note));
  } else {
    views.push(el("figure", { class: "chart bars", "data-chart": "worst-frame-stages", "data-marks": 0, "data-recorded": "false" },
      el("figcaption", { class: "chart-title" }, `Cell ${label}: the worst frame by stage`),
      el("p", { class: "note" }, "Not recorded: this results file has no worst_frame_stages_ms and no per-frame stage times (frame_stages_ms).")));
  }
  const totals = stageObject(cell.stages_ms);
  if (totals) {
    views.push(stageBars("stage-totals", `Cell ${label}: stage totals over the frames`, totals,
      "Each stage's time summed over every frame of a run, the median over the repetitions (stages_ms)."));
  }
  return views;
}
