// The dashboard's data: the JSON that `shatterbench history report` writes into the page's data element
// (harness/history/dashboard_data.h), read once, with the small lookups the views share.

/** The id of the data element (harness/history/dashboard/dashboard_html.h). */
export const DATA_ELEMENT_ID = "shatterbench-dashboard";

/** The page's data: {format, store, settings, commits, series}. */
export function readDashboardData(doc) {
  const element = doc.getElementById(DATA_ELEMENT_ID);
  if (!element) throw new Error(`the page has no data element #${DATA_ELEMENT_ID}`);
  const data = JSON.parse(element.textContent);
  if (data.format !== 1) throw new Error(`unknown dashboard data format ${data.format}`);
  return { store: data.store || "", settings: data.settings || {}, commits: data.commits || [], series: data.series || [] };
}

/** The first `n` hex digits of a sha. */
export function shortSha(sha, n = 8) {
  return String(sha || "").slice(0, n);
}

/** A committer time (s since 1970) as "YYYY-MM-DD". */
export function commitDate(time) {
  const d = new Date(Number(time) * 1000);
  return Number.isNaN(d.getTime()) ? "?" : d.toISOString().slice(0, 10);
}

/** A relative change (0.123) as "+12.3 %". */
export function formatChange(change) {
  if (!Number.isFinite(change)) return "-";
  return `${change >= 0 ? "+" : "\u2212"}${Math.abs(100 * change).toFixed(1)} %`;
}

/** True when the series' newest commit is an open (not acknowledged) regression. */
export function openRegression(series) {
  return Boolean(series.newest && series.newest.verdict === "regressed");
}

/**
 * The index into `points` ([[commit index, ...], ...], sorted by commit index) of the point nearest to
 * commit index `x`; -1 when there are no points.
 */
export function nearestPoint(points, x) {
  if (points.length === 0) return -1;
  let lo = 0;
  let hi = points.length - 1;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (points[mid][0] < x) lo = mid + 1;
    else hi = mid;
  }
  if (lo > 0 && Math.abs(points[lo - 1][0] - x) <= Math.abs(points[lo][0] - x)) return lo - 1;
  return lo;
}
