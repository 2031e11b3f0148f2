// The tables of the page: stability verdicts (`shatterbench stability --json`) and the runs of
// `shatterbench table --json`.

import { dataTable, el, formatMs, formatNumber } from "./dom.js";

const BAD_OUTCOMES = new Set(["CRASH", "TIMEOUT", "INVALID_OUTPUT"]);

function outcomeTag(outcome) {
  return String(outcome ?? "");
}

/** The verdicts of one stability results document as a table; `data-rows` = its rows. */
export function stabilityTable(results) {
  const rows = Array.isArray(results.results) ? results.results : [];
  const bad = rows.filter((r) => BAD_OUTCOMES.has(outcomeTag(r.outcome))).length;
  const summary = `${rows.length} case(s), ${bad} crashed, timed out or gave an invalid output${results.quick ? "; quick battery" : ""}.`;
  return el("div", { class: "table-view", "data-view": "stability" },
    el("p", { class: "note" }, summary),
    dataTable([
      { key: "hazard", label: "hazard" },
      { key: "algorithm", label: "algorithm" },
      { key: "kind", label: "kind" },
      { key: "outcome", label: "outcome", format: outcomeTag, className: (v) => (BAD_OUTCOMES.has(outcomeTag(v)) ? "bad" : "good") },
      { key: "worst_error", label: "worst error", format: formatNumber },
      { key: "fragments", label: "fragments" },
      { key: "converged", label: "converged", format: (v, r) => (r.kind === "stress" ? (v ? "yes" : "no") : "-") },
      { key: "residual", label: "residual", format: (v, r) => (r.kind === "stress" ? formatNumber(v) : "-") },
      { key: "time_ms", label: "time", format: formatMs },
      { key: "detail", label: "detail" },
    ], rows, { "data-table": "stability" }));
}

/** The rows of one table results document (`kind: "table"`); `data-rows` = its rows. */
export function runsTable(results) {
  const rows = Array.isArray(results.rows) ? results.rows : [];
  const figure = (name) => (v, r) => (r.figures && r.figures[name] !== undefined ? formatNumber(Number(r.figures[name])) : "");
  return el("div", { class: "table-view", "data-view": "table" },
    el("p", { class: "note" }, `${rows.length} row(s), ${results.repetitions ?? "?"} repetition(s) each: the median time, the error figures of seed 1.`),
    dataTable([
      { key: "mesh", label: "mesh" },
      { key: "triangles", label: "triangles" },
      { key: "algorithm", label: "algorithm" },
      { key: "fragments", label: "requested" },
      { key: "produced", label: "produced", value: (r) => r.produced ?? (r.refused !== undefined ? `refused: ${r.refused}` : r.failed !== undefined ? `failed: ${r.failed}` : "") },
      { key: "time_ms", label: "time", format: (v) => (v === undefined ? "" : formatMs(v)) },
      { key: "volume_error", label: "volume error", format: figure("volume_error") },
      { key: "partition_error", label: "partition error", format: figure("partition_error") },
      { key: "area_error", label: "area error", format: figure("area_error") },
      { key: "all_closed", label: "closed", value: (r) => (r.figures ? (r.figures.all_closed ? "yes" : "NO") : "") },
    ], rows, { "data-table": "table-runs" }));
}
