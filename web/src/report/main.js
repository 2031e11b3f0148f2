// The report page: reads the results files from the page's data element and draws every view.
// Everything it needs is in the page itself: it makes no network request (docs/report.md).

import "uplot/dist/uPlot.min.css";
import "./report.css";
import { readReportData, slowestCell } from "./data.js";
import { baseName, el, formatNumber } from "./dom.js";
import { heatMap, markSelected } from "./heat_map.js";
import { paretoChart, paretoGroups } from "./pareto.js";
import { cellStageViews } from "./stage_bars.js";
import { runsTable, stabilityTable } from "./tables.js";
import { timeline } from "./timeline.js";
import { fragmentGroups, fragmentsSection } from "./fragments_view.js";
import { playback } from "./playback.js";
import { schedulesSection } from "./schedules.js";
import { readRecordedFrames } from "./recorded_frames.js";
import { unpack } from "./inflate.js";

function contextLine(results) {
  const c = results.context || {};
  const parts = [];
  if (c.commit) parts.push(`commit ${c.commit}`);
  if (c.build_type) parts.push(c.build_type);
  if (c.cpu_model) parts.push(`${c.cpu_model}${c.cores ? `, ${c.cores} cores` : ""}`);
  if (c.date) parts.push(c.date);
  return parts.join(" · ");
}

function fileSection(kind, heading, entry) {
  return el("section", { class: "file-section", "data-section": kind, "data-file": entry.file },
    el("h2", {}, heading),
    el("p", { class: "source" }, `Source: ${baseName(entry.file)}`, contextLine(entry.results) ? ` · ${contextLine(entry.results)}` : ""));
}

function gridSection(entry) {
  const results = entry.results;
  const caseName = results.case && results.case.name ? results.case.name : "grid";
  const section = fileSection("grid", `Frame budget: ${caseName}`, entry);
  const cells = results.cells || [];
  const over = cells.filter((c) => c.failed !== undefined || !(c.worst_frame_ms <= results.budget_ms)).length;
  section.append(el("p", {}, `${cells.length} cells, ${over} over the ${formatNumber(results.budget_ms)} ms budget or failed; `
    + `${results.repetitions ?? "?"} repetition(s) of ${results.frames ?? "?"} frames per cell.`));
  const detail = el("div", { class: "cell-detail", "data-view": "cell-detail" });
  // The recordings of `grid --record-frames`, read once; a cell with one gets its playback.
  const recordings = entry.recorded_frames ? unpack(entry.recorded_frames).then(readRecordedFrames) : Promise.resolve([]);
  if (entry.recorded_frames) section.append(el("p", { "data-recorded": "" }, "This file has recorded frames: open a recorded cell to play its event."));
  let shown = 0;  // the latest selection wins when recordings arrive late
  const select = (cell, fromClick) => {
    const token = ++shown;
    return recordings.then((recs) => {
      if (token !== shown) return;
      const rec = recs.find((r) => r.prefracture === cell.prefracture && r.runtime === cell.runtime);
      let player = null;
      const view = timeline(cell, results.budget_ms, rec ? { onPick: (f) => player.show(f) } : {});
      if (rec) player = playback(rec, results, (f) => view.showFrame(f));
      detail.replaceChildren(view.element, ...(player ? [player.element] : []), ...cellStageViews(cell));
      detail.dataset.cell = `${cell.prefracture} x ${cell.runtime}`;
      view.mount();
      if (player) player.mount(Math.max(0, cell.samples?.[rec.repetition]?.event_frame ?? 0));
      markSelected(map, cell);
      if (fromClick) detail.scrollIntoView({ block: "nearest" });
    });
  };
  const map = heatMap(results, (cell) => select(cell, true));
  section.append(map, detail);
  const first = slowestCell(results);
  return { element: section, mount: () => (first ? select(first, false) : undefined) };
}

function accuracySection(entry) {
  const section = fileSection("accuracy", "Accuracy against time", entry);
  const charts = paretoGroups(entry.results).map(paretoChart);
  if (charts.length === 0) section.append(el("p", { class: "note" }, "This file has no points."));
  for (const c of charts) section.append(c.element);
  return { element: section, mount: () => charts.forEach((c) => c.mount()) };
}

function tableSection(kind, heading, entry, draw) {
  const section = fileSection(kind, heading, entry);
  section.append(draw(entry.results));
  return { element: section, mount() {} };
}

function render() {
  const data = readReportData(document);
  const root = document.getElementById("report") || document.body;
  const sections = [
    ...data.grids.map(gridSection),
    schedulesSection(data.grids),
    ...data.accuracy.map(accuracySection),
    ...data.stability.map((e) => tableSection("stability", "Stability verdicts", e, stabilityTable)),
    ...data.tables.map((e) => tableSection("table", "Fracture table", e, runsTable)),
    ...fragmentGroups(data.fragments).map(fragmentsSection),
  ].filter(Boolean);
  const counts = [[data.grids.length, "grid"], [data.accuracy.length, "accuracy"], [data.stability.length, "stability"], [data.tables.length, "table"],
    [data.fragments.length, "fragments folder"]]
    .filter(([n]) => n > 0).map(([n, what]) => `${n} ${what}`);
  root.append(el("header", {},
    el("h1", {}, "shatterbench report"),
    el("p", { class: "note" }, `From ${counts.join(", ") || "no"} results file(s), read by shatterbench report. Views: docs/report.md.`)));
  for (const s of sections) root.append(s.element);
  // 3D views load their glTF binaries asynchronously: `data-drawn` says when every view has drawn.
  return Promise.all(sections.map((s) => s.mount()));
}

try {
  render().then(() => { document.body.dataset.drawn = "true"; }, (error) => {
    document.body.dataset.drawn = "error";
    console.error(error);
  });
  document.body.dataset.ready = "true";
} catch (error) {
  document.body.dataset.ready = "error";
  document.body.append(el("p", { class: "error" }, `The report could not be drawn: ${error && error.message ? error.message : error}`));
  console.error(error);
}
