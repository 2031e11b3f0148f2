// The schedules side by side: when grid files run the same case and cell under different schedules
// (`grid --schedule immediate|prefetch|amortized`, docs/pipeline.md), one view per cell puts their
// frame times on one chart (the first repetition of each) and their figures in one table. Answers
// "which schedule keeps this event inside the budget, and what latency does it cost?".

import uPlot from "uplot";
import { chartWidth, dataTable, el, formatMs, formatNumber } from "./dom.js";

const SCHEDULE_COLOURS = { immediate: "#c92a2a", prefetch: "#1f4e9e", amortized: "#2b8a3e" };

const median = (values) => {
  const v = values.filter(Number.isFinite).sort((a, b) => a - b);
  const n = v.length;
  return n === 0 ? NaN : n % 2 ? v[(n - 1) / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
};

/**
 * The cells run under more than one schedule, over every grid entry: one group per case, cell and
 * algorithms, each with its runs `{schedule, cell, budget, file}` in file order (a schedule once).
 */
export function scheduleGroups(grids) {
  const groups = new Map();
  for (const entry of grids) {
    const results = entry.results;
    for (const cell of results.cells || []) {
      if (cell.failed !== undefined || !cell.schedule) continue;
      const caseName = results.case && results.case.name ? results.case.name : "grid";
      const key = JSON.stringify([caseName, cell.prefracture, cell.runtime, cell.prefracturer, cell.fracturer, cell.stress]);
      if (!groups.has(key)) groups.set(key, { caseName, cell, runs: [] });
      const group = groups.get(key);
      if (!group.runs.some((r) => r.schedule === cell.schedule))
        group.runs.push({ schedule: cell.schedule, cell, budget: results.budget_ms, file: entry.file });
    }
  }
  return [...groups.values()].filter((g) => g.runs.length > 1);
}

function scheduleView(group) {
  const { caseName, cell, runs } = group;
  const figure = el("figure", { class: "chart schedules", "data-chart": "schedules", "data-cell": `${cell.prefracture} x ${cell.runtime}`,
    "data-marks": runs.length },
    el("figcaption", { class: "chart-title" }, `${caseName}, cell ${cell.prefracture} x ${cell.runtime}: the schedules side by side`),
    el("p", { class: "note" }, "Time per frame of each schedule's first repetition; the dashed red line is the budget."));
  const host = el("div", { class: "plot" });
  figure.append(host);
  figure.append(dataTable([
    { key: "schedule", label: "schedule" },
    { label: "worst frame", value: (r) => r.cell.worst_frame_ms, format: formatMs },
    { label: "most event work in a frame", value: (r) => median((r.cell.samples || []).map((s) => s.worst_work_ms)), format: formatMs },
    { label: "largest step", value: (r) => r.cell.largest_step_ms, format: formatMs },
    { label: "latency", value: (r) => r.cell.latency_ms, format: formatMs },
    { label: "latency frames", value: (r) => r.cell.latency_frames, format: (v) => formatNumber(v) },
    { label: "within budget", value: (r) => (r.cell.within_budget ? "yes" : "no") },
  ], runs, { "data-table": "schedules" }));
  const series = runs.map((r) => (r.cell.samples && r.cell.samples[0] && Array.isArray(r.cell.samples[0].frame_ms) ? r.cell.samples[0].frame_ms : []));
  const frames = Math.max(0, ...series.map((s) => s.length));
  return {
    element: figure,
    mount() {
      if (frames === 0) return;
      const x = Array.from({ length: frames }, (_, i) => i);
      const budget = runs[0].budget;
      const data = [x, ...series.map((s) => x.map((i) => (i < s.length ? s[i] : null)))];
      const options = {
        width: chartWidth(host),
        height: 260,
        scales: { x: { time: false } },
        axes: [{ label: "frame" }, { label: "ms", size: 60 }],
        series: [{ label: "frame" }, ...runs.map((r) => ({ label: r.schedule, stroke: SCHEDULE_COLOURS[r.schedule] || "#495057", width: 1.5,
          points: { show: false }, value: (u, v) => (v === null || v === undefined ? "-" : formatNumber(v)) }))],
        hooks: {
          draw: [(u) => {
            if (!(u.scales.y.max >= budget)) return;
            const y = Math.round(u.valToPos(budget, "y", true));
            const { left, width } = u.bbox;
            u.ctx.save();
            u.ctx.strokeStyle = "#c92a2a";
            u.ctx.setLineDash([5 * devicePixelRatio, 4 * devicePixelRatio]);
            u.ctx.beginPath();
            u.ctx.moveTo(left, y);
            u.ctx.lineTo(left + width, y);
            u.ctx.stroke();
            u.ctx.restore();
          }],
        },
      };
      new uPlot(options, data, host);
    },
  };
}

/** A section with one view per cell run under several schedules, or null when there is none. */
export function schedulesSection(grids) {
  const groups = scheduleGroups(grids);
  if (groups.length === 0) return null;
  const views = groups.map(scheduleView);
  const section = el("section", { class: "file-section", "data-section": "schedules" },
    el("h2", {}, "Schedules side by side"),
    el("p", { class: "note" }, `${groups.length} cell(s) run under more than one schedule (grid --schedule): `
      + "immediate runs the whole event in the impact frame, prefetch runs its fracture ahead while the projectile flies, "
      + "amortized spreads its steps over frames (docs/pipeline.md)."),
    views.map((v) => v.element));
  return { element: section, mount: () => views.forEach((v) => v.mount()) };
}
