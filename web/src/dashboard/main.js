// The history dashboard (docs/dashboard.md): reads the store's series from the page's data element and
// lists them, open regressions first, each with its trend over the commits and its change points.
// Everything it needs is in the page itself: it makes no network request.

import "uplot/dist/uPlot.min.css";
import "./dashboard.css";
import { el } from "../report/dom.js";
import { commitDate, readDashboardData, shortSha } from "./data.js";
import { filterBar } from "./filters.js";
import { lazyCharts } from "./lazy_charts.js";
import { seriesCard } from "./series_card.js";

function summary(data) {
  const { commits, series } = data;
  const changes = series.reduce((n, s) => n + s.changes.length, 0);
  const regressed = series.filter((s) => s.newest && s.newest.verdict === "regressed").length;
  const span = commits.length > 0
    ? `${commits.length} commit(s) from ${shortSha(commits[0].sha)} (${commitDate(commits[0].time)}) to `
      + `${shortSha(commits[commits.length - 1].sha)} (${commitDate(commits[commits.length - 1].time)})`
    : "no commit";
  const s = data.settings;
  return el("p", { class: "note", "data-summary": "", "data-series": series.length, "data-commits": commits.length,
    "data-changes": changes, "data-regressed": regressed },
  `${series.length} series over ${span}; ${changes} change point(s); ${regressed} open regression(s). `
    + `Store: ${data.store}. Change points: window ${s.window}, max p-value ${s.max_pvalue}, min magnitude ${s.min_magnitude}.`);
}

async function render() {
  const data = readDashboardData(document);
  const root = document.getElementById("dashboard") || document.body;
  root.append(el("header", { class: "page-head" },
    el("h1", {}, "shatterbench history"),
    summary(data),
    el("p", { class: "note" }, "Each chart: the commit medians (line), the smallest to largest sample of each commit (band), "
      + "the change points (dashed: red a regression, green an improvement). Hover a chart to read a commit.")));
  if (data.series.length === 0) {
    root.append(el("p", { class: "empty", "data-empty": "" }, "No series: the store has no run that matches the filter."));
    return;
  }
  const cards = data.series.map((s) => seriesCard(s, data.commits));
  const shown = el("p", { class: "shown", "data-shown": cards.length }, "");
  const showCount = (n) => {
    shown.dataset.shown = String(n);
    shown.textContent = `Showing ${n} of ${cards.length} series.`;
  };
  const nothing = el("p", { class: "empty", hidden: "" }, "No series matches these filters.");
  const bar = filterBar(data.series, (match) => {
    let n = 0;
    for (const c of cards) {
      const visible = match(c.series);
      c.element.hidden = !visible;
      if (visible) n++;
    }
    nothing.hidden = n > 0;
    showCount(n);
  });
  showCount(cards.length);
  root.append(el("div", { class: "sticky" }, bar.element, shown), nothing,
    el("div", { class: "series-list" }, cards.map((c) => c.element)));
  await lazyCharts(cards);
}

const started = performance.now();
render().then(() => {
  document.body.dataset.firstScreenMs = String(Math.round(performance.now()));
  document.body.dataset.renderMs = String(Math.round(performance.now() - started));
  document.body.dataset.ready = "true";
}, (error) => {
  document.body.dataset.ready = "error";
  document.body.append(el("p", { class: "error" }, `The dashboard could not be drawn: ${error && error.message ? error.message : error}`));
  console.error(error);
});
