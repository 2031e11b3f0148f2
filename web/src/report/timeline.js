// One cell's frame timeline: milliseconds per frame, every repetition its own line, the budget as a
// dashed line and the event frame marked. When the results carry per-frame stage times
// (`samples[k].frame_stages_ms`: stage -> ms per frame), the first repetition's stages are stacked under
// the lines. Answers "why did this cell spike?": which frame, how far over, and in which stage.

import uPlot from "uplot";
import { chartWidth, el, formatMs, formatNumber } from "./dom.js";

const RUN_COLOURS = ["#1f4e9e", "#d9480f", "#2b8a3e", "#7048e8", "#c2255c", "#0b7285", "#5c940d", "#862e9c"];
const STAGE_COLOURS = ["#a5d8ff", "#ffd8a8", "#b2f2bb", "#d0bfff", "#fcc2d7", "#99e9f2", "#ffec99", "#dee2e6", "#eebefa"];

const KNOWN_STAGES = ["prefracture", "bonds", "runtime_fracture", "bond_update", "stress", "falling_clusters", "colliders", "physics", "debris"];

/** The colour of stage `name`, shared by the timeline and the stage bars so one stage is one colour. */
export function stageColour(name) {
  let k = KNOWN_STAGES.indexOf(name);
  if (k < 0) k = [...String(name)].reduce((h, c) => (h * 31 + c.charCodeAt(0)) >>> 0, 7);
  return STAGE_COLOURS[k % STAGE_COLOURS.length];
}

/** Per-frame stage arrays of a sample as [name, values] pairs, or [] when the file has none. */
export function frameStages(sample, frames) {
  const stages = sample && sample.frame_stages_ms;
  if (!stages || typeof stages !== "object") return [];
  return Object.entries(stages).filter(([, v]) => Array.isArray(v) && v.length === frames && v.some((x) => x > 0));
}

/**
 * Draws a dashed line on the chart's canvas from (x0, y0) to (x1, y1), canvas pixels, and a label at
 * (lx, ly) aligned `align` ("left" or "right") there.
 */
function dashedLine(u, colour, [x0, y0, x1, y1], label, [lx, ly], align) {
  const ctx = u.ctx;
  const px = devicePixelRatio;
  ctx.save();
  ctx.strokeStyle = colour;
  ctx.setLineDash([5 * px, 4 * px]);
  ctx.lineWidth = 1.5 * px;
  ctx.beginPath();
  ctx.moveTo(x0, y0);
  ctx.lineTo(x1, y1);
  ctx.stroke();
  ctx.fillStyle = colour;
  ctx.font = `${11 * px}px sans-serif`;
  ctx.textAlign = align;
  ctx.textBaseline = "alphabetic";
  ctx.fillText(label, lx, ly);
  ctx.restore();
}

/**
 * A uPlot plugin that marks frame `frame` with a vertical line and the budget `budget` ms with a
 * horizontal one (when the y axis reaches it). Drawn on the canvas, not as series, so that they take no
 * part in the axes' ranges.
 */
function markers(frame, budget, playhead) {
  return {
    hooks: {
      draw: (u) => {
        const { left, top, width, height } = u.bbox;
        const px = devicePixelRatio;
        if (playhead.frame >= 0) {
          const x = Math.round(u.valToPos(playhead.frame, "x", true));
          const ctx = u.ctx;
          ctx.save();
          ctx.strokeStyle = "#212529";
          ctx.lineWidth = 2 * px;
          ctx.beginPath();
          ctx.moveTo(x, top);
          ctx.lineTo(x, top + height);
          ctx.stroke();
          ctx.restore();
        }
        if (frame >= 0) {
          const x = Math.round(u.valToPos(frame, "x", true));
          dashedLine(u, "#495057", [x, top, x, top + height], "event", [x + 4 * px, top + 12 * px], "left");
        }
        if (u.scales.y.max >= budget) {
          const y = Math.round(u.valToPos(budget, "y", true));
          dashedLine(u, "#c92a2a", [left, y, left + width, y], `budget ${formatNumber(budget)} ms`, [left + width - 4 * px, y - 4 * px], "right");
        }
      },
    },
  };
}

/**
 * The timeline of `cell` of a grid results document (budget `budget` ms) in a new element, with the
 * uPlot chart made once the element is in the page (call `mount()` after appending). With `onPick`,
 * a click on the chart calls it with the frame under the pointer, and `showFrame(f)` draws the shown
 * frame of a playback as a solid line (`data-playhead`). The element
 * carries `data-chart="timeline"`, `data-cell` ("P x R"), `data-marks` (one line per repetition with frames),
 * `data-frames`, `data-event-frame` and `data-stacked-stages` (stages stacked; 0 without per-frame
 * stage times).
 */
export function timeline(cell, budget, { onPick } = {}) {
  const title = `Cell ${cell.prefracture} x ${cell.runtime}: time per frame`;
  const figure = el("figure", { class: "chart timeline", "data-chart": "timeline", "data-cell": `${cell.prefracture} x ${cell.runtime}` },
    el("figcaption", { class: "chart-title" }, title));
  if (cell.failed !== undefined) {
    figure.dataset.marks = "0";
    figure.append(el("p", { class: "note" }, `This cell failed and has no frames: ${cell.failed}`));
    return { element: figure, mount() {}, showFrame() {} };
  }
  const samples = (cell.samples || []).filter((s) => Array.isArray(s.frame_ms) && s.frame_ms.length > 0);
  const frames = Math.max(0, ...samples.map((s) => s.frame_ms.length));
  const eventFrame = samples.length > 0 && Number.isInteger(samples[0].event_frame) ? samples[0].event_frame : -1;
  const stages = frameStages(samples[0], frames);
  figure.dataset.marks = String(samples.length);
  figure.dataset.frames = String(frames);
  figure.dataset.eventFrame = String(eventFrame);
  figure.dataset.stackedStages = String(stages.length);
  const notes = [];
  notes.push(`${samples.length} repetition(s) of ${frames} frames; worst frame ${formatMs(cell.worst_frame_ms)} (median over the repetitions of each one's slowest), budget ${formatNumber(budget)} ms.`);
  notes.push("The dashed red line is the budget.");
  if (eventFrame >= 0) notes.push(`The dashed vertical line is the event frame (${eventFrame}).`);
  notes.push(stages.length > 0
    ? "The filled areas stack the first repetition's stage times per frame."
    : "Per-frame stage times are not recorded in this results file (samples[].frame_stages_ms): only the frame totals are drawn.");
  figure.append(el("p", { class: "note" }, notes.join(" ")));
  const host = el("div", { class: "plot" });
  figure.append(host);
  if (frames === 0) {
    figure.append(el("p", { class: "note" }, "This cell has no per-frame samples."));
    return { element: figure, mount() {}, showFrame() {} };
  }

  const x = Array.from({ length: frames }, (_, i) => i);
  const data = [x];
  const series = [{ label: "frame" }];
  // Stages stacked: each series is the running sum, drawn from the top one down, each filled to zero,
  // so every band shows one stage.
  const sums = [];
  let running = new Array(frames).fill(0);
  for (const [, values] of stages) {
    running = running.map((v, i) => v + values[i]);
    sums.push(running);
  }
  for (let k = stages.length - 1; k >= 0; k--) {
    data.push(sums[k]);
    series.push({ label: `${stages[k][0]} (run 1)`, stroke: "rgba(0,0,0,0.15)", width: 0.5, fill: stageColour(stages[k][0]), points: { show: false },
      value: (u, v, si, i) => (i === null || i === undefined ? "-" : formatNumber(stages[k][1][i])) });
  }
  samples.forEach((s, k) => {
    data.push(s.frame_ms.length === frames ? s.frame_ms : x.map((i) => (i < s.frame_ms.length ? s.frame_ms[i] : null)));
    series.push({ label: `run ${k + 1} (seed ${s.seed})`, stroke: RUN_COLOURS[k % RUN_COLOURS.length], width: 1.5, points: { show: false },
      value: (u, v) => (v === null || v === undefined ? "-" : formatNumber(v)) });
  });

  // The y axis reaches the budget by default (how far under it the frames are); "fit" zooms to the frames.
  let fit = false;
  const playhead = { frame: -1 };
  let chart = null;
  const toggle = el("button", { type: "button", class: "scale-toggle", "data-action": "fit-frames" }, "Zoom to the frames");
  figure.insertBefore(toggle, host);
  return {
    element: figure,
    mount() {
      const options = {
        width: chartWidth(host),
        height: 320,
        scales: { x: { time: false }, y: { range: (u, min, max) => [0, (fit && max > 0 ? max : Math.max(max || 0, budget)) * 1.08] } },
        axes: [{ label: "frame" }, { label: "ms", size: 60 }],
        series,
        legend: { live: true },
        plugins: [markers(eventFrame, budget, playhead)],
      };
      chart = new uPlot(options, data, host);
      if (onPick) {
        chart.over.style.cursor = "pointer";
        chart.over.addEventListener("click", () => {
          const f = Math.round(chart.posToVal(chart.cursor.left, "x"));
          if (Number.isFinite(f) && f >= 0 && f < frames) onPick(f);
        });
      }
      toggle.addEventListener("click", () => {
        fit = !fit;
        toggle.textContent = fit ? "Show the budget" : "Zoom to the frames";
        figure.dataset.yScale = fit ? "frames" : "budget";
        chart.setData(data);
      });
      figure.dataset.yScale = "budget";
    },
    showFrame(f) {
      playhead.frame = f;
      figure.dataset.playhead = String(f);
      if (chart) chart.redraw(false, false);
    },
  };
}
