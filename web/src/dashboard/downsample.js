// What a trend chart draws: every point when there are few, else per pixel column the commits with the
// smallest and the largest median (so that a spike stays visible) and the column's whole spread
// (smallest sample to largest). Only the drawing is reduced: a hover reads the full data (data.js).

/**
 * Columns of `points` ([[commit index, median, min, max, n], ...], sorted by commit index) to draw over
 * commit indices `first`..`last` in `buckets` columns: {x, median, low, high} arrays of one length, at
 * most 2 x `buckets` long (per column the commits of the smallest and the largest median, in commit
 * order, each with the column's smallest and largest sample). With at most 2 x `buckets` points every
 * point is kept as it is.
 */
export function downsample(points, first, last, buckets) {
  const out = { x: [], median: [], low: [], high: [] };
  const push = (p, low, high) => {
    out.x.push(p[0]);
    out.median.push(p[1]);
    out.low.push(low);
    out.high.push(high);
  };
  if (points.length <= 2 * buckets) {
    for (const p of points) push(p, p[2], p[3]);
    return out;
  }
  const span = Math.max(1, last - first);
  let i = 0;
  while (i < points.length) {
    const bucket = Math.min(buckets - 1, Math.floor(((points[i][0] - first) / span) * buckets));
    let minAt = i;
    let maxAt = i;
    let low = points[i][2];
    let high = points[i][3];
    let j = i + 1;
    for (; j < points.length && Math.min(buckets - 1, Math.floor(((points[j][0] - first) / span) * buckets)) === bucket; j++) {
      if (points[j][1] < points[minAt][1]) minAt = j;
      if (points[j][1] > points[maxAt][1]) maxAt = j;
      low = Math.min(low, points[j][2]);
      high = Math.max(high, points[j][3]);
    }
    for (const k of minAt === maxAt ? [minAt] : [Math.min(minAt, maxAt), Math.max(minAt, maxAt)]) push(points[k], low, high);
    i = j;
  }
  return out;
}
