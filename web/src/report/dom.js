// Small DOM helpers. Text from a results file only ever reaches the page as textContent or an attribute
// value, never as markup (docs/report.md, "Escaping").

/** An element `tag` with attributes `attrs` (null and undefined skipped) and children (strings become text). */
export function el(tag, attrs = {}, ...children) {
  const node = document.createElement(tag);
  for (const [name, value] of Object.entries(attrs)) {
    if (value === null || value === undefined) continue;
    if (name === "class") node.className = value;
    else node.setAttribute(name, String(value));
  }
  for (const child of children.flat()) {
    if (child === null || child === undefined || child === false) continue;
    node.append(child instanceof Node ? child : document.createTextNode(String(child)));
  }
  return node;
}

/** A milliseconds figure with three significant digits: "0.0123 ms", "4.56 ms", "312 ms". */
export function formatMs(ms) {
  if (!Number.isFinite(ms)) return "-";
  return `${formatNumber(ms)} ms`;
}

/** A number with three significant digits, without exponent between 1e-4 and 1e6. */
export function formatNumber(x) {
  if (!Number.isFinite(x)) return "-";
  if (x === 0) return "0";
  const magnitude = Math.abs(x);
  if (magnitude < 1e-4 || magnitude >= 1e6) return x.toExponential(2).replace(/\.?0+e/, "e");
  return Number(x.toPrecision(3)).toString();
}

/** The file name at the end of `path` (the data element keeps the path as given). */
export function baseName(path) {
  const parts = String(path).split(/[\\/]/);
  return parts[parts.length - 1] || String(path);
}

/** A table with a header row `columns` ({key, label, format?}) and one row per item of `rows`. */
export function dataTable(columns, rows, attrs = {}) {
  const head = el("tr", {}, columns.map((c) => el("th", { scope: "col" }, c.label)));
  const body = rows.map((row) =>
    el(
      "tr",
      {},
      columns.map((c) => {
        const value = c.value ? c.value(row) : row[c.key];
        const text = c.format ? c.format(value, row) : value === undefined || value === null ? "" : String(value);
        return el("td", { class: c.className ? c.className(value, row) : null }, text);
      }),
    ),
  );
  return el("table", { class: "data-table", "data-rows": rows.length, ...attrs }, el("thead", {}, head), el("tbody", {}, body));
}

/** The width a chart inside `container` gets: its width, within 320..1100 px. */
export function chartWidth(container) {
  const w = container.clientWidth || 800;
  return Math.max(320, Math.min(1100, w));
}
