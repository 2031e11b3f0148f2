// One series on the dashboard: what it measures, its newest verdict, its trend chart (made only while
// the card is on screen: lazy_charts.js) and the list of its change points.

import { chartWidth, el, formatNumber } from "../report/dom.js";
import { changeColour } from "./change_marks.js";
import { commitDate, formatChange, openRegression, shortSha } from "./data.js";
import { CHART_HEIGHT, trendChart } from "./trend_chart.js";

function verdictBadge(series) {
  const n = series.newest;
  if (!n) return el("span", { class: "badge none" }, "no direction: never judged");
  const ack = n.acknowledged ? ` (acknowledged at ${shortSha(n.acknowledged.commit)}: ${n.acknowledged.note})` : "";
  if (n.verdict === "regressed") return el("span", { class: "badge regressed" }, `open regression ${formatChange(n.change)}`, ack);
  if (n.verdict === "improved") return el("span", { class: "badge improved" }, `improved ${formatChange(n.change)}`, ack);
  if (n.verdict === "new") return el("span", { class: "badge none" }, "new: no baseline yet", ack);
  return el("span", { class: "badge same" }, "newest commit: same", ack);
}

function changeList(series, commits) {
  const unit = series.unit ? ` ${series.unit}` : "";
  const items = series.changes.map((c) => {
    const point = series.points[c.index];
    const commit = point ? commits[point[0]] || {} : {};
    return el("li", { class: `change ${c.kind}`, "data-commit": c.commit, "data-kind": c.kind },
      el("span", { class: "swatch", style: `background:${changeColour(c.kind)}` }),
      `${c.kind} at ${shortSha(c.commit, 12)} (${commitDate(commit.time)}): ${formatChange(c.change)}, `
        + `${formatNumber(c.before)} \u2192 ${formatNumber(c.after)}${unit}, p ${formatNumber(c.pvalue)}`);
  });
  if (items.length === 0) return el("p", { class: "note changes", "data-changes": 0 }, "No change point.");
  return el("ol", { class: "changes", "data-changes": items.length }, items);
}

/**
 * The card of `series` (an entry of the data's `series`): {element, mount(), unmount()}. The element
 * carries data-series (the id), data-case, data-fracturer, data-what, data-metric, data-kind,
 * data-points (commits in the data), data-changes and data-regressed; its figure, once drawn,
 * data-drawn and data-drawn-change-marks.
 */
export function seriesCard(series, commits) {
  const unit = series.unit || "ratio";
  const better = series.better === "none" ? "no direction" : `${series.better} is better`;
  const figure = el("figure", { class: "trend", "data-chart": "trend", "data-points": series.points.length,
    "data-change-marks": series.changes.length });
  const host = el("div", { class: "plot", style: `min-height:${CHART_HEIGHT}px` });
  const readout = el("p", { class: "readout", "aria-live": "polite" }, "\u00a0");
  figure.append(host, readout);
  const element = el("article", {
    class: `series-card${openRegression(series) ? " regressed" : ""}`,
    "data-series": series.id, "data-case": series.case, "data-fracturer": series.fracturer, "data-what": series.what,
    "data-metric": series.metric, "data-kind": series.kind, "data-points": series.points.length,
    "data-changes": series.changes.length, "data-regressed": openRegression(series) },
  el("header", {},
    el("h2", {}, `${series.case} \u00b7 ${series.subject}`),
    el("p", { class: "meta" }, `${series.what} \u00b7 ${series.metric} (${unit}, ${better}) \u00b7 ${series.kind} \u00b7 `
      + `${series.points.length} commit(s) \u00b7 fingerprint ${shortSha(series.fingerprint, 12)} `, verdictBadge(series))),
  figure, changeList(series, commits));

  let chart = null;
  return {
    element,
    series,
    mount() {
      if (chart) return;
      chart = trendChart(series, commits, host, figure, readout, chartWidth(host));
    },
    unmount() {
      if (!chart) return;
      chart.destroy();
      chart = null;
      delete figure.dataset.drawn;
      delete figure.dataset.drawnChangeMarks;
    },
    get mounted() { return chart !== null; },
  };
}
