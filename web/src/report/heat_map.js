// The grid's heat map: one cell per (pre-fracture, runtime) pair, coloured by its worst frame against
// the budget on a log scale. Answers "where does the budget break?": every cell over the budget is
// orange to red and marked "!". Hover shows the value; a click opens the cell's timeline.

import { BudgetColourScale } from "./colour_scale.js";
import { el, formatMs, formatNumber } from "./dom.js";

function uniqueSorted(values) {
  return [...new Set(values)].sort((a, b) => a - b);
}

function cellLabel(cell) {
  return `${cell.prefracture} x ${cell.runtime}`;
}

function legend(scale) {
  const bar = el("div", { class: "legend-bar", style: `background: ${scale.gradient()}` });
  const axis = el("div", { class: "legend-axis" });
  for (const v of scale.ticks()) {
    axis.append(el("span", { class: "legend-tick", style: `left: ${(100 * scale.position(v)).toFixed(2)}%` }, formatNumber(v)));
  }
  const budget = el(
    "div",
    { class: "legend-budget", style: `left: ${(100 * scale.budgetPosition()).toFixed(2)}%`, "data-budget-ms": scale.budget },
    el("span", {}, `budget ${formatNumber(scale.budget)} ms`),
  );
  return el("div", { class: "legend", "aria-label": "colour scale, ms, logarithmic" }, bar, budget, axis,
    el("div", { class: "legend-caption" }, "worst frame, ms (log scale)"));
}

/**
 * Draws the heat map of a grid results document into a new element and returns it. `onSelect(cell)`
 * is called when a cell that ran is clicked. The container carries `data-marks` (cells drawn) and
 * `data-over-budget` (cells over the budget or failed).
 */
export function heatMap(results, onSelect) {
  const budget = results.budget_ms;
  const cells = results.cells;
  const rows = uniqueSorted(cells.map((c) => c.prefracture));
  const columns = uniqueSorted(cells.map((c) => c.runtime));
  const scale = new BudgetColourScale(cells.filter((c) => c.failed === undefined).map((c) => c.worst_frame_ms), budget);
  const readout = el("div", { class: "readout", "aria-live": "polite" }, "Hover a cell for its worst frame; click it for its timeline.");

  const grid = el("div", { class: "heat-grid", role: "grid", style: `grid-template-columns: auto repeat(${columns.length}, minmax(3.2em, 1fr))` });
  grid.append(el("div", { class: "heat-corner" }, "pre-fracture \\ runtime"));
  for (const r of columns) grid.append(el("div", { class: "heat-column-head", role: "columnheader" }, String(r)));
  let marks = 0;
  let over = 0;
  for (const p of rows) {
    grid.append(el("div", { class: "heat-row-head", role: "rowheader" }, String(p)));
    for (const r of columns) {
      const cell = cells.find((c) => c.prefracture === p && c.runtime === r);
      if (!cell) {
        grid.append(el("div", { class: "heat-empty" }));
        continue;
      }
      marks++;
      const failed = cell.failed !== undefined;
      const ms = cell.worst_frame_ms;
      const overBudget = failed || !(ms <= budget);
      if (overBudget) over++;
      const text = failed
        ? `${cellLabel(cell)}: failed (${cell.failed})`
        : `${cellLabel(cell)}: worst frame ${formatMs(ms)}, ${overBudget ? "over" : "within"} the ${formatNumber(budget)} ms budget`;
      const button = el(
        "button",
        {
          type: "button",
          class: `heat-cell${failed ? " failed" : ""}${overBudget ? " over" : ""}`,
          "data-prefracture": cell.prefracture,
          "data-runtime": cell.runtime,
          "data-value-ms": failed ? null : ms,
          title: text,
          "aria-label": text,
          style: failed ? null : `background: ${scale.colour(ms)}; color: ${scale.textColour(ms)}`,
        },
        failed ? "failed" : `${formatNumber(ms)}${overBudget ? " !" : ""}`,
      );
      button.addEventListener("mouseenter", () => (readout.textContent = text));
      button.addEventListener("focus", () => (readout.textContent = text));
      button.addEventListener("click", () => onSelect(cell));
      grid.append(button);
    }
  }
  return el(
    "figure",
    { class: "chart heat-map", "data-chart": "heat-map", "data-marks": marks, "data-over-budget": over, "data-budget-ms": budget },
    el("figcaption", {}, `Worst frame per cell against the ${formatNumber(budget)} ms budget: rows pre-fracture, columns runtime fragments`),
    grid,
    legend(scale),
    readout,
  );
}

/** Marks the cell at (pre-fracture, runtime) as the one shown below the map. */
export function markSelected(heatMapElement, cell) {
  for (const b of heatMapElement.querySelectorAll(".heat-cell")) {
    const chosen = Number(b.dataset.prefracture) === cell.prefracture && Number(b.dataset.runtime) === cell.runtime;
    b.classList.toggle("selected", chosen);
    b.setAttribute("aria-pressed", chosen ? "true" : "false");
  }
}
