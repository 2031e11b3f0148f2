// The change points on a trend chart's canvas: a dashed vertical line at the commit that starts each new
// level, labelled with its short sha and the relative change, red for a regression, green for an
// improvement, grey for a change of a metric without a direction.

import { formatChange, shortSha } from "./data.js";

/** The colour of a change of kind `kind` ("regression", "improvement", "change"). */
export function changeColour(kind) {
  if (kind === "regression") return "#c92a2a";
  if (kind === "improvement") return "#2b8a3e";
  return "#868e96";
}

/**
 * A uPlot plugin that marks each of `changes` ({index, commit, change, kind}; index into `points`) at
 * its commit; `onDrawn(n)` is told how many marks the last draw made.
 */
export function changeMarks(changes, points, onDrawn) {
  return {
    hooks: {
      draw: (u) => {
        const { top, height, left, width } = u.bbox;
        const px = devicePixelRatio;
        const ctx = u.ctx;
        let drawn = 0;
        ctx.save();
        ctx.font = `${10 * px}px sans-serif`;
        ctx.textBaseline = "top";
        for (const c of changes) {
          const point = points[c.index];
          if (!point) continue;
          const x = Math.round(u.valToPos(point[0], "x", true));
          if (x < left - 1 || x > left + width + 1) continue;
          ctx.strokeStyle = ctx.fillStyle = changeColour(c.kind);
          ctx.setLineDash([4 * px, 3 * px]);
          ctx.lineWidth = 1.5 * px;
          ctx.beginPath();
          ctx.moveTo(x, top);
          ctx.lineTo(x, top + height);
          ctx.stroke();
          const label = `${shortSha(c.commit, 7)} ${formatChange(c.change)}`;
          const right = x + 4 * px + ctx.measureText(label).width > left + width;
          ctx.textAlign = right ? "right" : "left";
          ctx.fillText(label, right ? x - 4 * px : x + 4 * px, top + 2 * px + (drawn % 2) * 12 * px);
          drawn++;
        }
        ctx.restore();
        onDrawn(drawn);
      },
    },
  };
}
