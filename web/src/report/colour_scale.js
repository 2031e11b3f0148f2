// The heat map's colour scale: logarithmic in milliseconds, so that 2 ms and 4 ms are as far apart as
// 20 ms and 40 ms, with a break in hue at the budget. Under the budget the colours run from deep blue
// (fast) through teal to yellow-green (close to the budget); over it from orange to a dark red, so a
// cell over the budget is never mistaken for one under it, whatever its shade.

const UNDER = ["#27306b", "#2c5d9e", "#218f8d", "#3fb96f", "#b7dd3a"];
const OVER = ["#f59f2a", "#e0582a", "#b3202a", "#5e0c1a"];

function hexToRgb(hex) {
  const n = parseInt(hex.slice(1), 16);
  return [(n >> 16) & 255, (n >> 8) & 255, n & 255];
}

function mix(stops, t) {
  const x = Math.min(1, Math.max(0, t)) * (stops.length - 1);
  const i = Math.min(stops.length - 2, Math.floor(x));
  const a = hexToRgb(stops[i]);
  const b = hexToRgb(stops[i + 1]);
  const f = x - i;
  return a.map((v, k) => Math.round(v + (b[k] - v) * f));
}

/**
 * A log colour scale for values in ms around `budget` ms. The domain spans the values given and the
 * budget with some room on both sides, so the budget is always inside the legend.
 */
export class BudgetColourScale {
  constructor(values, budget) {
    const positive = values.filter((v) => Number.isFinite(v) && v > 0);
    const low = Math.min(budget / 4, ...positive);
    const high = Math.max(budget * 2, ...positive);
    this.budget = budget;
    this.logLow = Math.log10(low / 1.25);
    this.logHigh = Math.log10(high * 1.25);
    this.logBudget = Math.log10(budget);
  }

  /** Position of `ms` along the legend, 0..1 (log). */
  position(ms) {
    const v = Math.log10(Math.max(ms, 10 ** this.logLow));
    return Math.min(1, Math.max(0, (v - this.logLow) / (this.logHigh - this.logLow)));
  }

  /** The budget's position along the legend, 0..1. */
  budgetPosition() {
    return this.position(this.budget);
  }

  /** The colour of `ms` as [r, g, b]. */
  rgb(ms) {
    const b = this.budgetPosition();
    const p = this.position(ms);
    if (ms <= this.budget) return mix(UNDER, b > 0 ? p / b : 1);
    return mix(OVER, b < 1 ? (p - b) / (1 - b) : 1);
  }

  /** The colour of `ms` as a CSS colour. */
  colour(ms) {
    const [r, g, b] = this.rgb(ms);
    return `rgb(${r}, ${g}, ${b})`;
  }

  /** Black or white, whichever reads better on the colour of `ms`. */
  textColour(ms) {
    const [r, g, b] = this.rgb(ms);
    const luminance = 0.2126 * r + 0.7152 * g + 0.0722 * b;
    return luminance > 140 ? "#111" : "#fff";
  }

  /** Tick values for the legend: 1, 2, 5 times powers of ten inside the domain. */
  ticks() {
    const out = [];
    for (let e = Math.floor(this.logLow); e <= Math.ceil(this.logHigh); e++) {
      for (const m of [1, 2, 5]) {
        const v = m * 10 ** e;
        const lv = Math.log10(v);
        if (lv >= this.logLow && lv <= this.logHigh) out.push(v);
      }
    }
    return out;
  }

  /** A CSS linear-gradient of the whole legend, left (fast) to right (slow). */
  gradient() {
    const stops = [];
    const n = 48;
    for (let i = 0; i <= n; i++) {
      const ms = 10 ** (this.logLow + ((this.logHigh - this.logLow) * i) / n);
      stops.push(`${this.colour(ms)} ${((100 * i) / n).toFixed(2)}%`);
    }
    // A sharp edge at the budget: the last colour under it, then the first over it.
    const at = (100 * this.budgetPosition()).toFixed(2);
    stops.push(`${this.colour(this.budget)} ${at}%`, `${this.colour(this.budget * 1.0001)} ${at}%`);
    stops.sort((a, b) => parseFloat(a.split(" ").pop()) - parseFloat(b.split(" ").pop()));
    return `linear-gradient(to right, ${stops.join(", ")})`;
  }
}
