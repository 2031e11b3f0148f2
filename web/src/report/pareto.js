// Time against error for one family and case of an accuracy results file, log-log: one point per
// algorithm setting, the Pareto front (no other point both faster and more accurate) ringed and joined
// by a dashed line. Answers "which algorithm gives the least error for the time I can spend?".

import uPlot from "uplot";
import { chartWidth, dataTable, el, formatMs, formatNumber } from "./dom.js";

const COLOURS = ["#1f4e9e", "#d9480f", "#2b8a3e", "#7048e8", "#c2255c", "#0b7285", "#5c940d", "#862e9c", "#495057"];

/** The (family, case) groups of an accuracy results document, in file order. */
export function paretoGroups(results) {
  const groups = [];
  for (const p of results.points || []) {
    let g = groups.find((x) => x.family === p.family && x.caseName === p.case);
    if (!g) groups.push((g = { family: p.family, caseName: p.case, points: [] }));
    g.points.push(p);
  }
  return groups;
}

/** uPlot axis filter: on a log axis spanning more than two decades, ticks and grid lines at powers of ten only. */
function decadesOnly(u, splits) {
  const values = splits.filter((v) => v > 0);
  if (values.length === 0 || Math.log10(Math.max(...values) / Math.min(...values)) <= 2) return splits;
  return splits.map((v) => (v > 0 && Math.abs(Math.log10(v) - Math.round(Math.log10(v))) < 1e-9 ? v : null));
}

/** A log axis label at 1, 2 and 5 times a power of ten, none between. */
function oneTwoFive(v) {
  if (!(v > 0)) return "";
  const mantissa = Math.round(v / 10 ** Math.floor(Math.log10(v) + 1e-9));
  return mantissa === 1 || mantissa === 2 || mantissa === 5 ? formatNumber(v) : "";
}

/** True when `p` can be drawn: a positive time and a finite error. */
export function drawable(p) {
  return Number.isFinite(p.time_ms) && p.time_ms > 0 && Number.isFinite(p.error);
}

function pointText(p) {
  return `${p.algorithm} ${p.knob}: ${formatMs(p.time_ms)}, error ${formatNumber(p.error)}${p.pareto ? " (on the front)" : ""}`;
}

/**
 * The chart of one group in a new element (call `mount()` once it is in the page). The element carries
 * `data-chart="pareto"`, `data-family`, `data-case`, `data-marks` (points drawn) and `data-front-marks`
 * (front points drawn, each ringed).
 */
export function paretoChart(group) {
  const points = group.points.filter(drawable).sort((a, b) => a.time_ms - b.time_ms);
  const front = points.filter((p) => p.pareto === true);
  const skipped = group.points.length - points.length;
  const positive = points.map((p) => p.error).filter((e) => e > 0);
  const floor = positive.length > 0 ? Math.min(...positive) / 10 : 1e-16;
  const y = (p) => (p.error > 0 ? p.error : floor);
  const title = `${group.family}: ${group.caseName}, time against error`;
  const figure = el("figure", {
    class: "chart pareto", "data-chart": "pareto", "data-family": group.family, "data-case": group.caseName,
    "data-marks": points.length, "data-front-marks": front.length,
  }, el("figcaption", { class: "chart-title" }, title));
  const notes = [`${points.length} point(s), ${front.length} on the Pareto front (ringed, joined by the dashed line). Both axes are logarithmic.`];
  if (points.some((p) => p.error === 0)) notes.push(`An error of exactly 0 is drawn at ${formatNumber(floor)}.`);
  if (skipped > 0) notes.push(`${skipped} point(s) have no error or no time (a model without forces, or a failed run) and are not drawn.`);
  figure.append(el("p", { class: "note" }, notes.join(" ")));
  const host = el("div", { class: "plot" });
  const readout = el("div", { class: "readout", "aria-live": "polite" }, "Hover a point for its setting, time and error.");
  figure.append(host, readout);
  figure.append(dataTable([
    { key: "algorithm", label: "algorithm" },
    { key: "knob", label: "setting" },
    { key: "time_ms", label: "time", format: (v) => formatMs(v) },
    { key: "error", label: "error", format: (v) => (v === null || v === undefined ? "none" : formatNumber(v)) },
    { key: "pareto", label: "front", format: (v) => (v ? "yes" : "") },
  ], group.points, { "data-table": "pareto-points" }));

  const algorithms = [...new Set(points.map((p) => p.algorithm))];
  const x = points.map((p) => p.time_ms);
  const data = [x];
  const series = [{ label: "time, ms" }];
  algorithms.forEach((name, k) => {
    data.push(points.map((p) => (p.algorithm === name ? y(p) : null)));
    const colour = COLOURS[k % COLOURS.length];
    series.push({ label: name, stroke: colour, paths: () => null, points: { show: true, space: 0, size: 7, fill: colour, stroke: colour } });
  });
  data.push(points.map((p) => (p.pareto === true ? y(p) : null)));
  series.push({ label: "Pareto front", stroke: "#212529", width: 1.25, dash: [6, 4], spanGaps: true,
    points: { show: true, space: 0, size: 13, width: 1.5, stroke: "#212529", fill: "rgba(0,0,0,0)" } });

  return {
    element: figure,
    mount() {
      if (points.length === 0) return;
      const nearest = (u) => {
        const { left, top } = u.cursor;
        if (left === undefined || left < 0) return undefined;
        let best;
        let bestDistance = 14 * 14;
        points.forEach((p) => {
          const dx = u.valToPos(p.time_ms, "x") - left;
          const dy = u.valToPos(y(p), "y") - top;
          const d = dx * dx + dy * dy;
          if (d <= bestDistance) { best = p; bestDistance = d; }
        });
        return best;
      };
      const options = {
        width: chartWidth(host),
        height: 340,
        scales: { x: { time: false, distr: 3 }, y: { distr: 3 } },
        axes: [{ label: "time, ms (log)", filter: (self, splits) => splits, values: (self, ticks) => ticks.map(oneTwoFive) }, { label: "error (log)", size: 70, filter: decadesOnly, grid: { filter: decadesOnly }, ticks: { filter: decadesOnly },
          values: (u, ticks) => ticks.map((v) => (v === null ? "" : formatNumber(v))) }],
        series,
        legend: { live: false },
        cursor: { points: { show: false } },
        hooks: {
          setCursor: [(u) => {
            const p = nearest(u);
            readout.textContent = p ? pointText(p) : "Hover a point for its setting, time and error.";
          }],
        },
      };
      new uPlot(options, data, host);
    },
  };
}
