// The filter bar: one menu per facet (case, fracturer, stage or part, metric), each listing only the
// values that series of the data have, with their counts, and "open regressions only".

import { el } from "../report/dom.js";
import { openRegression } from "./data.js";

/** The facets: the key of a series, the menu's label, the card's data attribute. */
export const FACETS = [
  { key: "case", label: "Case" },
  { key: "fracturer", label: "Fracturer" },
  { key: "what", label: "Stage" },
  { key: "metric", label: "Metric" },
];

/** The values of `key` over `series` with their counts, sorted by value. */
function facetValues(series, key) {
  const counts = new Map();
  for (const s of series) counts.set(s[key], (counts.get(s[key]) || 0) + 1);
  return [...counts.entries()].sort(([a], [b]) => String(a).localeCompare(String(b)));
}

/**
 * The filter bar for `series`; `onChange(match)` is called with a predicate over series whenever a
 * control changes. Returns {element, match} (match: the current predicate).
 */
export function filterBar(series, onChange) {
  const chosen = Object.fromEntries(FACETS.map((f) => [f.key, null]));
  let regressionsOnly = false;
  const match = (s) => (!regressionsOnly || openRegression(s)) && FACETS.every((f) => chosen[f.key] === null || s[f.key] === chosen[f.key]);
  const controls = FACETS.map((f) => {
    const values = facetValues(series, f.key);
    const select = el("select", { "data-filter": f.key, "aria-label": f.label },
      el("option", { value: "" }, `all (${values.length})`),
      values.map(([v, n], k) => el("option", { value: String(k) }, `${v === "" ? "(none)" : v} (${n})`)));
    select.addEventListener("change", () => {
      chosen[f.key] = select.value === "" ? null : values[Number(select.value)][0];
      onChange(match);
    });
    return el("label", { class: "filter" }, `${f.label} `, select);
  });
  const regressed = series.filter(openRegression).length;
  const box = el("input", { type: "checkbox", "data-filter": "regressed" });
  box.addEventListener("change", () => {
    regressionsOnly = box.checked;
    onChange(match);
  });
  const element = el("div", { class: "filter-bar", role: "search" }, controls,
    el("label", { class: "filter" }, box, ` open regressions only (${regressed})`));
  return { element, match };
}
