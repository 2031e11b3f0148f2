// One series' trend over the commits: the commit medians as a line, the samples' spread (smallest to
// largest sample of each commit) as a band, the change points marked. The x axis is the commit index of
// the whole history, so every chart lines up. What is drawn is downsampled to about one column per
// pixel (downsample.js); the readout under the chart shows the hovered commit from the full data.

import uPlot from "uplot";
import { formatNumber } from "../report/dom.js";
import { changeMarks } from "./change_marks.js";
import { commitDate, formatChange, nearestPoint, shortSha } from "./data.js";
import { downsample } from "./downsample.js";

/** Height of a trend chart's plot, px (the card reserves it before the chart is made). */
export const CHART_HEIGHT = 200;

/** The readout's text for point `k` of `series` (every value exact, from the data). */
export function pointText(series, k, commits) {
  const [index, median, low, high, n] = series.points[k];
  const commit = commits[index] || {};
  const unit = series.unit ? ` ${series.unit}` : "";
  const parts = [`commit ${shortSha(commit.sha, 12)} (${commitDate(commit.time)}${commit.branch ? `, ${commit.branch}` : ""})`,
    `median ${formatNumber(median)}${unit}`, `samples ${formatNumber(low)} \u2013 ${formatNumber(high)}${unit} (${n})`];
  const change = series.changes.find((c) => c.index === k);
  if (change) parts.push(`${change.kind} ${formatChange(change.change)} (p ${formatNumber(change.pvalue)})`);
  return parts.join(" \u00b7 ");
}

/**
 * Makes the chart of `series` in `host` (an empty element `width` px wide); `figure` receives
 * `data-drawn` (points drawn) and `data-drawn-change-marks`, `readout` the hovered commit. Returns the
 * uPlot instance (destroy() it when the chart leaves the screen).
 */
export function trendChart(series, commits, host, figure, readout, width) {
  const first = 0;
  const last = Math.max(1, commits.length - 1);
  // Columns of 2 px (the plot is the chart less its y axis): at most one drawn point per pixel.
  const drawn = downsample(series.points, first, last, Math.max(8, Math.round((width - 70) / 2)));
  figure.dataset.drawn = String(drawn.x.length);
  const options = {
    width,
    height: CHART_HEIGHT,
    legend: { show: false },
    cursor: { drag: { x: false, y: false }, points: { show: false } },
    scales: { x: { time: false, range: [first - 0.5, last + 0.5] } },
    axes: [
      { values: (u, splits) => splits.map((v) => (Number.isInteger(v) && commits[v] ? shortSha(commits[v].sha, 7) : "")) },
      { size: 64, values: (u, splits) => splits.map(formatNumber) },
    ],
    series: [
      {},
      { label: "largest sample", stroke: "rgba(31,78,158,0.25)", width: 1, points: { show: false } },
      { label: "median", stroke: "#1f4e9e", width: 1.5, points: { show: (u) => drawn.x.length * 6 < u.bbox.width / devicePixelRatio } },
      { label: "smallest sample", stroke: "rgba(31,78,158,0.25)", width: 1, points: { show: false } },
    ],
    bands: [{ series: [1, 3], fill: "rgba(31,78,158,0.12)" }],
    hooks: {
      setCursor: [(u) => {
        const left = u.cursor.left;
        if (left === undefined || left < 0) {
          readout.textContent = "\u00a0";
          delete figure.dataset.hover;
          return;
        }
        const k = nearestPoint(series.points, u.posToVal(left, "x"));
        if (k < 0) return;
        figure.dataset.hover = String(series.points[k][0]);
        readout.textContent = pointText(series, k, commits);
      }],
    },
    plugins: [changeMarks(series.changes, series.points, (n) => { figure.dataset.drawnChangeMarks = String(n); })],
  };
  return new uPlot(options, [drawn.x, drawn.high, drawn.median, drawn.low], host);
}
