// The report's data: the results files as `shatterbench report` read them, in the page's one JSON element.

/** The id of the element that holds the data (harness/report/html/report_html.cpp writes it). */
export const DATA_ELEMENT_ID = "shatterbench-data";

/**
 * Reads and parses the data element of `doc`. The object holds four lists of results files, each of
 * {file, results}: `grids` (with `recorded_frames` when recorded), `accuracy`, `stability`, `tables`;
 * and `fragments`, the fragments folders (docs/report.md, "The data").
 */
export function readReportData(doc) {
  const element = doc.getElementById(DATA_ELEMENT_ID);
  if (!element) throw new Error(`the page has no #${DATA_ELEMENT_ID} element`);
  const data = JSON.parse(element.textContent);
  for (const key of ["grids", "accuracy", "stability", "tables", "fragments"]) {
    if (!Array.isArray(data[key])) data[key] = [];
  }
  return data;
}

/** The cells of a grid results document that ran (no `failed` key). */
export function cellsThatRan(results) {
  return results.cells.filter((c) => c.failed === undefined);
}

/** The cell the page opens first: the one with the largest worst frame among those that ran. */
export function slowestCell(results) {
  let best;
  for (const c of cellsThatRan(results)) if (!best || c.worst_frame_ms > best.worst_frame_ms) best = c;
  return best;
}
