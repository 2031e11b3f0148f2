// The history dashboard in a real browser (ctest: browser_dashboard, label browser; docs/dashboard.md).
//
//   node tests/browser/dashboard_page_test.mjs --cli build/bin/shatterbench --web build/web \
//        --work build/browser-dashboard-test --screenshots build/browser-screenshots \
//        [--chromium /usr/bin/chromium] [--docs-image docs/images/dashboard.png]
//
// 1. A store of real runs: two grids of the built command line (building, plane-slice and voronoi), each
//    recorded at 12 commits of a fresh git repository with its times scaled a little per commit (the
//    voronoi grid +80 % from the ninth commit on), and a copy of the plane-slice grid whose case is named
//    `</script><script>alert(1)</script>`, recorded on a branch of that name. `history report` writes
//    dashboard.html; the page is opened from file:// in headless Chromium (puppeteer-core from the build
//    folder's node_modules; no browser is downloaded) and checked: no console error, page error, dialog
//    or request other than file:, data: or blob:; one card per series of the store, the points and the
//    change points of each equal to the page's data, the change points in total equal to `history
//    changes`; every drawn chart draws every point and change point; regressions first; a filter lists
//    only the matching series; a hover reads the commit from the data; a page of no series says so.
//    Screenshots go to --screenshots (and the top of the page to --docs-image when given).
// 2. 1,000 commits x 500 series, the data made here and put into the same page: it opens, draws the
//    first screen (charts only on screen, each downsampled to the pixel width, the hover reading the full
//    data), and the time it takes is printed (a measurement, not a check).
// Exit 0 when every check passed, 1 otherwise (a missing browser included: never a skip).

import { execFileSync } from "node:child_process";
import fs from "node:fs";
import { createRequire } from "node:module";
import path from "node:path";
import { pathToFileURL } from "node:url";
import { downsample } from "../../web/src/dashboard/downsample.js";
import { nearestPoint } from "../../web/src/dashboard/data.js";

const HOSTILE = "</script><script>alert(1)</script>";
const COMMITS = 12;
const STEP_AT = 8;

function parseArgs(argv) {
  const args = { chromium: "/usr/bin/chromium" };
  for (let i = 0; i < argv.length; i += 2) {
    const key = argv[i].replace(/^--/, "").replace(/-([a-z])/g, (_, c) => c.toUpperCase());
    args[key] = argv[i + 1];
  }
  for (const key of ["cli", "web", "work", "screenshots"]) {
    if (!args[key]) throw new Error(`--${key} is required`);
  }
  return args;
}

let passed = 0;
const failures = [];
function check(condition, what) {
  if (condition) passed++;
  else failures.push(what);
}

/** Runs a program (no shell); its standard output. Exit codes in `ok` are accepted. */
function run(program, args, { cwd, env, ok = [0] } = {}) {
  try {
    return execFileSync(program, args, { cwd, env: { ...process.env, ...env }, stdio: ["ignore", "pipe", "pipe"] }).toString();
  } catch (error) {
    if (ok.includes(error.status)) return String(error.stdout);
    throw new Error(`${path.basename(program)} ${args.join(" ")}: exit ${error.status}: ${String(error.stderr).trim()}`);
  }
}

/** A git repository with `count` empty commits a day apart; their shas in order. */
function makeRepository(dir, count) {
  fs.mkdirSync(dir, { recursive: true });
  run("git", ["init", "-q", "-b", "main"], { cwd: dir });
  const shas = [];
  for (let i = 0; i < count; i++) {
    const when = `${1767225600 + 86400 * i} +0000`;
    run("git", ["-c", "user.name=t", "-c", "user.email=t@example.org", "commit", "-q", "--allow-empty", `--date=${when}`, "-m", `c${i}`],
      { cwd: dir, env: { GIT_COMMITTER_DATE: when } });
    shas.push(run("git", ["rev-parse", "HEAD"], { cwd: dir }).trim());
  }
  return shas;
}

/** A copy of `value` with every number under a key ending in `_ms` (a budget's aside) times `factor`. */
function scaleTimes(value, factor, timed = false) {
  if (typeof value === "number") return timed ? value * factor : value;
  if (Array.isArray(value)) return value.map((v) => scaleTimes(v, factor, timed));
  if (value && typeof value === "object") {
    return Object.fromEntries(Object.entries(value).map(([k, v]) =>
      [k, scaleTimes(v, factor, timed || (k.endsWith("_ms") && !k.includes("budget")))]));
  }
  return value;
}

/** A grid results document with its cells' times scaled by `factor` (its settings, and so its series, kept). */
function scaledGrid(results, factor) {
  return { ...results, cells: scaleTimes(results.cells, factor) };
}

/** The store of part 1: real grids recorded at every commit; returns {db, store facts}. */
function makeStore(cli, work) {
  const repo = path.join(work, "repo");
  const shas = makeRepository(repo, COMMITS);
  const db = path.join(work, "history.sqlite");
  const grids = {};
  for (const fracturer of ["plane-slice", "voronoi"]) {
    const file = path.join(work, `grid-${fracturer}.json`);
    run(cli, ["grid", "--case", "building", "--fracturer", fracturer, "--prefracture", "10", "--runtime", "5", "--repetitions", "5",
      "--frames", "20", "--no-cache", "--json", file], { ok: [0, 1] });
    grids[fracturer] = JSON.parse(fs.readFileSync(file, "utf8"));
  }
  const hostile = structuredClone(grids["plane-slice"]);
  hostile.case.name = HOSTILE;
  const runs = [["plane-slice", grids["plane-slice"], false, "main"], ["voronoi", grids.voronoi, true, "main"],
    ["hostile", hostile, false, HOSTILE]];
  for (let i = 0; i < COMMITS; i++) {
    for (const [name, results, stepped, branch] of runs) {
      // A deterministic wobble of +-1 % per commit; the stepped grid 80 % slower from STEP_AT on.
      const factor = (1 + 0.01 * Math.sin(7 * i + name.length)) * (stepped && i >= STEP_AT ? 1.8 : 1);
      const file = path.join(work, `run-${name}-${i}.json`);
      fs.writeFileSync(file, JSON.stringify(scaledGrid(results, factor)));
      run(cli, ["history", "record", file, "--db", db, "--commit", shas[i], "--repo", repo, "--branch", branch]);
    }
  }
  // What `history changes` finds in the same store: its series and one table row per change point.
  const changes = run(cli, ["history", "changes", "--db", db]);
  const head = /^(\d+) series, (\d+) with change points/.exec(changes);
  const rows = changes.split("\n").filter((l) => l.startsWith("| ") && !l.startsWith("| series |"));
  return { db, shas, seriesCount: head ? Number(head[1]) : -1, changeCount: rows.length };
}

/** Opens `url` in a new page that fails on any request but file:, data:, blob:, console errors and dialogs. */
async function openGuarded(browser, url, label, viewport) {
  const page = await browser.newPage();
  await page.setViewport(viewport);
  const requests = [];
  await page.setRequestInterception(true);
  page.on("request", (request) => {
    requests.push(request.url());
    if (/^(file|data|blob):/.test(request.url())) request.continue();
    else {
      failures.push(`${label}: a network request to ${request.url()}`);
      request.abort();
    }
  });
  page.on("console", (m) => { if (m.type() === "error") failures.push(`${label}: console error: ${m.text()}`); });
  page.on("pageerror", (e) => failures.push(`${label}: page error: ${e.message}`));
  page.on("dialog", async (d) => {
    failures.push(`${label}: a dialog opened (${d.message()}): script from the store ran`);
    await d.dismiss();
  });
  const started = performance.now();
  await page.goto(url, { waitUntil: "load", timeout: 120000 });
  await page.waitForFunction(() => document.body.dataset.ready !== undefined, { timeout: 120000 });
  const openMs = performance.now() - started;
  const ready = await page.evaluate(() => document.body.dataset.ready);
  check(ready === "true", `${label}: the page did not draw (data-ready=${ready})`);
  check(requests.length === 1 && requests[0] === url, `${label}: loaded more than itself: ${JSON.stringify(requests.slice(0, 5))}`);
  return { page, openMs };
}

/** The page's data element, parsed. */
function pageData(file) {
  const html = fs.readFileSync(file, "utf8");
  const m = /<script type="application\/json" id="shatterbench-dashboard">([^<]*)<\/script>/.exec(html);
  if (!m) throw new Error(`${file}: no data element`);
  return JSON.parse(m[1]);
}

/** Every card's facts, and every drawn chart's. */
function cardFacts(page) {
  return page.$$eval(".series-card", (cards) => cards.map((c) => {
    const figure = c.querySelector('[data-chart="trend"]');
    return {
      id: c.dataset.series, hidden: c.hidden, fracturer: c.dataset.fracturer, caseName: c.dataset.case,
      points: Number(c.dataset.points), changes: Number(c.dataset.changes), regressed: c.dataset.regressed === "true",
      listed: c.querySelectorAll("li.change").length, title: c.querySelector("h2").textContent,
      drawn: figure.dataset.drawn === undefined ? null : Number(figure.dataset.drawn),
      drawnMarks: figure.dataset.drawnChangeMarks === undefined ? null : Number(figure.dataset.drawnChangeMarks),
      canvas: figure.querySelectorAll("canvas").length,
    };
  }));
}

/** Hovers the first drawn chart at `share` of its plot's width; the figure's hovered commit and readout. */
async function hoverChart(page, share) {
  const box = await page.$eval('.series-card:not([hidden]) [data-chart="trend"][data-drawn] .u-over', (e) => {
    const r = e.getBoundingClientRect();
    return { x: r.left, y: r.top, width: r.width, height: r.height };
  });
  await page.mouse.move(box.x + share * box.width, box.y + box.height / 2);
  return page.$eval('.series-card:not([hidden]) [data-chart="trend"][data-drawn]', (f) => ({
    series: f.closest(".series-card").dataset.series, hover: f.dataset.hover === undefined ? null : Number(f.dataset.hover),
    readout: f.querySelector(".readout").textContent }));
}

/** Checks of part 1 on the page of the recorded store. */
async function checkRecorded(page, data, store) {
  const cards = await cardFacts(page);
  check(cards.length === data.series.length, `cards: ${cards.length}, the data has ${data.series.length} series`);
  check(cards.length === store.seriesCount, `cards: ${cards.length}, history changes lists ${store.seriesCount} series`);
  const byId = new Map(data.series.map((s) => [s.id, s]));
  let changes = 0;
  for (const c of cards) {
    const s = byId.get(c.id);
    check(s !== undefined, `a card for series ${c.id}, which the data does not have`);
    if (!s) continue;
    changes += c.changes;
    check(c.points === s.points.length && s.points.length === COMMITS, `${c.title}: ${c.points} points, data ${s.points.length}`);
    check(c.changes === s.changes.length && c.listed === s.changes.length, `${c.title}: ${c.listed} changes listed, data ${s.changes.length}`);
    if (c.drawn !== null) {
      check(c.drawn === s.points.length, `${c.title}: ${c.drawn} points drawn, ${s.points.length} in the data`);
      check(c.drawnMarks === s.changes.length, `${c.title}: ${c.drawnMarks} change marks drawn, ${s.changes.length} in the data`);
      check(c.canvas > 0, `${c.title}: no canvas`);
    }
  }
  check(changes === store.changeCount, `change points on the page: ${changes}, history changes: ${store.changeCount}`);
  check(changes > 0, "the store's stepped grid gave no change point");
  const drawnCards = cards.filter((c) => c.drawn !== null).length;
  check(drawnCards > 0 && drawnCards < cards.length, `charts drawn: ${drawnCards} of ${cards.length} (only those near the screen)`);
  const firstOther = cards.findIndex((c) => !c.regressed);
  check(cards.some((c) => c.regressed), "no open regression, though the voronoi grid stepped +80 % four commits ago");
  check(cards.slice(firstOther).every((c) => !c.regressed), "open regressions are not all listed first");
  check(cards.filter((c) => c.regressed).every((c) => c.fracturer === "voronoi"), "a series regressed that did not step");

  // The hostile case name is text; the page holds only its two scripts.
  check(cards.some((c) => c.title.includes(HOSTILE)), "the hostile case name is not shown as text");
  check(await page.$$eval("script", (els) => els.length) === 2, "the page has a script other than its data and bundle");

  // Hover: the readout names the hovered commit and its median from the data.
  const h = await hoverChart(page, 0.5);
  check(h.hover !== null, "hovering a chart set no commit");
  if (h.hover !== null) {
    const sha = data.commits[h.hover].sha.slice(0, 12);
    check(h.readout.includes(`commit ${sha}`), `the readout "${h.readout}" does not name commit ${sha}`);
  }

  // Filters: each narrows the cards to the matching series, and resets.
  const shownCount = () => page.$eval("[data-shown]", (e) => Number(e.dataset.shown));
  const visible = async () => (await cardFacts(page)).filter((c) => !c.hidden);
  await page.select('select[data-filter="fracturer"]', "1");  // sorted: plane-slice, voronoi
  const voronoi = await visible();
  const wantVoronoi = data.series.filter((s) => s.fracturer === "voronoi").length;
  check(voronoi.length === wantVoronoi && voronoi.every((c) => c.fracturer === "voronoi"),
    `fracturer voronoi: ${voronoi.length} cards shown, ${wantVoronoi} series match`);
  check(await shownCount() === wantVoronoi, "the shown count does not follow the fracturer filter");
  const metrics = await page.$$eval('select[data-filter="metric"] option', (o) => o.map((x) => x.textContent));
  const cpu = metrics.findIndex((t) => t.startsWith("cpu_ms "));
  await page.select('select[data-filter="metric"]', String(cpu - 1));
  const both = await visible();
  const wantBoth = data.series.filter((s) => s.fracturer === "voronoi" && s.metric === "cpu_ms").length;
  check(both.length === wantBoth && wantBoth > 0 && wantBoth < wantVoronoi, `voronoi and cpu_ms: ${both.length} shown, ${wantBoth} match`);
  await page.waitForFunction(() => document.querySelector('.series-card:not([hidden]) [data-chart="trend"][data-drawn]') !== null);
  await page.screenshot({ path: path.join(store.screenshots, "dashboard-filtered.png") });
  await page.click('input[data-filter="regressed"]');
  const regressed = await visible();
  check(regressed.length > 0 && regressed.every((c) => c.regressed), "open regressions only: shows other series");
  await page.click('input[data-filter="regressed"]');
  await page.select('select[data-filter="metric"]', "");
  await page.select('select[data-filter="fracturer"]', "");
  const caseNames = await page.$$eval('select[data-filter="case"] option', (o) => o.map((x) => x.textContent));
  check(caseNames.some((t) => t.startsWith(HOSTILE)), "the case filter does not list the hostile case name as text");
  check((await visible()).length === data.series.length, "the filters, reset, do not show every series again");
}

/** 1,000 commits x 500 series as dashboard_data would give them, every tenth series with a step. */
function largeData(commitCount, seriesCount) {
  let seed = 12345;
  const random = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
  const hex = () => Array.from({ length: 40 }, () => "0123456789abcdef"[Math.floor(random() * 16)]).join("");
  const commits = Array.from({ length: commitCount }, (_, i) => ({ sha: hex(), time: 1767225600 + 3600 * i, branch: "main" }));
  const cases = ["building", "bridge", "tower", "wall", "column"];
  const fracturers = ["plane-slice", "voronoi", "fem-lite", "cgal-clip"];
  const stages = ["worst frame", "stage physics", "stage stress", "stage colliders", "event frame"];
  const metricNames = ["cpu_ms", "time_ms", "instructions", "volume_error", "partition_error"];
  const series = [];
  for (let k = 0; k < seriesCount; k++) {
    const step = k % 10 === 0 ? Math.floor(commitCount * 0.8) : -1;
    const points = [];
    for (let i = 0; i < commitCount; i++) {
      const level = (1 + (k % 7)) * (step >= 0 && i >= step ? 1.25 : 1);
      const median = level * (1 + 0.02 * (random() - 0.5)) + (i === 500 ? level : 0);  // one spike per series
      points.push([i, median, median * 0.97, median * 1.03, 5]);
    }
    const changes = step >= 0
      ? [{ index: step, commit: commits[step].sha, before: 1, after: 1.25, change: 0.25, pvalue: 1e-9, kind: "regression" }]
      : [];
    series.push({ id: k.toString(16).padStart(16, "0"), kind: "grid", case: cases[k % 5], subject: `${10 * (1 + (k % 10))} x 5 ${fracturers[(k >> 1) % 4]}`,
      what: stages[Math.floor(k / 5) % 5], metric: metricNames[Math.floor(k / 25) % 5], unit: "ms", better: "lower", fingerprint: "f".repeat(16),
      fracturer: fracturers[(k >> 1) % 4], points, changes,
      newest: { verdict: step >= 0 ? "regressed" : "same", change: step >= 0 ? 0.25 : 0, pvalue: 0.5, note: "" } });
  }
  series.sort((a, b) => Number(b.newest.verdict === "regressed") - Number(a.newest.verdict === "regressed"));
  return { format: 1, store: "synthetic", settings: { window: 30, max_pvalue: 0.001, min_magnitude: 0 }, commits, series };
}

/** `html` with its data element holding `data` (escaped as the C++ side escapes it). */
function withData(html, data) {
  const text = JSON.stringify(data).replace(/</g, "\\u003c").replace(/>/g, "\\u003e").replace(/&/g, "\\u0026");
  const open = '<script type="application/json" id="shatterbench-dashboard">';
  const begin = html.indexOf(open) + open.length;
  const end = html.indexOf("</script>", begin);
  return html.slice(0, begin) + text + html.slice(end);
}

/** The downsampling on its own: few points kept, many reduced to the columns, a spike kept. */
function checkDownsample() {
  const few = Array.from({ length: 10 }, (_, i) => [i, i, i - 1, i + 1, 3]);
  check(downsample(few, 0, 9, 100).x.length === 10, "downsample: 10 points in 100 columns are not all kept");
  const many = Array.from({ length: 1000 }, (_, i) => [i, i === 501 ? 50 : 1, 0.9, i === 700 ? 99 : 1.1, 5]);
  const d = downsample(many, 0, 999, 100);
  check(d.x.length <= 200 && d.x.length >= 100, `downsample: 1000 points in 100 columns gave ${d.x.length}`);
  check(d.x.includes(501) && Math.max(...d.median) === 50, "downsample: the spike of the medians is gone");
  check(Math.max(...d.high) === 99, "downsample: the largest sample is gone from the band");
  check(d.x.every((x, i) => i === 0 || x > d.x[i - 1]), "downsample: the columns are not in commit order");
  check(nearestPoint(many, 500.4) === 500 && nearestPoint(many, -3) === 0 && nearestPoint(many, 5000) === 999,
    "nearestPoint: not the nearest commit");
}

async function main() {
  const args = parseArgs(process.argv.slice(2));
  if (!fs.existsSync(args.chromium)) throw new Error(`no browser at ${args.chromium}: install Debian's chromium (scripts/install-deps)`);
  const require = createRequire(path.join(path.resolve(args.web), "package.json"));
  const puppeteer = require("puppeteer-core");
  checkDownsample();

  const work = path.resolve(args.work);
  fs.rmSync(work, { recursive: true, force: true });
  fs.mkdirSync(work, { recursive: true });
  fs.mkdirSync(args.screenshots, { recursive: true });
  const store = { ...makeStore(args.cli, work), screenshots: args.screenshots };
  const out = path.join(work, "dashboard");
  run(args.cli, ["history", "report", "--db", store.db, "--out", out]);
  const file = path.join(out, "dashboard.html");
  const data = pageData(file);

  const browser = await puppeteer.launch({
    executablePath: args.chromium,
    headless: true,
    args: ["--headless=new", "--no-sandbox", "--enable-unsafe-swiftshader", "--use-angle=swiftshader"],
  });
  try {
    const { page } = await openGuarded(browser, pathToFileURL(file).href, "dashboard.html", { width: 1240, height: 900 });
    await page.screenshot({ path: path.join(args.screenshots, "dashboard-top.png") });
    if (args.docsImage) await page.screenshot({ path: args.docsImage });
    await checkRecorded(page, data, store);
    await page.close();

    // A filter that matches nothing: a page that says so.
    const emptyOut = path.join(work, "dashboard-empty");
    run(args.cli, ["history", "report", "--db", store.db, "--out", emptyOut, "--case", "no such case"]);
    const empty = await openGuarded(browser, pathToFileURL(path.join(emptyOut, "dashboard.html")).href, "empty dashboard",
      { width: 1240, height: 900 });
    const emptyText = await empty.page.$eval("[data-empty]", (e) => e.textContent).catch(() => "");
    check(emptyText.startsWith("No series"), `a page of no series does not say so: "${emptyText}"`);
    await empty.page.close();

    // 1,000 commits x 500 series in the same page.
    const large = largeData(1000, 500);
    const largeFile = path.join(work, "dashboard-1000x500.html");
    fs.writeFileSync(largeFile, withData(fs.readFileSync(file, "utf8"), large));
    const opened = await openGuarded(browser, pathToFileURL(largeFile).href, "1000 x 500", { width: 1000, height: 900 });
    const timing = await opened.page.evaluate(() => ({ firstScreen: Number(document.body.dataset.firstScreenMs),
      render: Number(document.body.dataset.renderMs) }));
    const cards = await cardFacts(opened.page);
    const drawn = cards.filter((c) => c.drawn !== null);
    check(cards.length === 500, `1000 x 500: ${cards.length} cards, 500 series`);
    check(drawn.length > 0 && drawn.length <= 12, `1000 x 500: ${drawn.length} charts drawn on the first screen (only those near it)`);
    check(drawn.every((c) => c.drawn < 1000 && c.drawn >= 100), `1000 x 500: drawn points ${drawn.map((c) => c.drawn)}, not downsampled`);
    check(drawn.every((c) => c.drawnMarks === c.changes), "1000 x 500: change marks drawn differ from the data");
    const h = await hoverChart(opened.page, 0.37);
    const s = large.series.find((x) => x.id === h.series);
    check(h.hover !== null && s && h.readout.includes(`commit ${large.commits[h.hover].sha.slice(0, 12)}`),
      `1000 x 500: the hover does not read commit ${h.hover} from the data: "${h.readout}"`);
    await opened.page.screenshot({ path: path.join(args.screenshots, "dashboard-1000x500.png") });
    // Scrolled to the end: the charts there are made, the first ones gone.
    await opened.page.evaluate(() => window.scrollTo(0, document.body.scrollHeight));
    await opened.page.waitForFunction(() => document.querySelector('.series-card:last-child [data-chart="trend"][data-drawn]') !== null, { timeout: 10000 });
    const after = await cardFacts(opened.page);
    check(after[0].drawn === null && after[after.length - 1].drawn !== null, "1000 x 500: charts are not made and dropped as the page scrolls");
    const mb = (fs.statSync(largeFile).size / 1e6).toFixed(1);
    console.log(`browser_dashboard: 1000 commits x 500 series: page ${mb} MB; opened and first screen drawn in ${Math.round(opened.openMs)} ms `
      + `(page's own clock: ${timing.firstScreen} ms from navigation, ${timing.render} ms in its script); `
      + `${drawn.length} charts drawn, ${Math.max(...drawn.map((c) => c.drawn))} or fewer of the 1000 points each`);
    await opened.page.close();
  } finally {
    await browser.close();
  }
}

try {
  await main();
} catch (error) {
  failures.push(`error: ${error && error.stack ? error.stack : error}`);
}
for (const f of failures) console.error(`browser_dashboard: FAILED: ${f}`);
console.log(`browser_dashboard: ${passed} passed, ${failures.length} failed`);
process.exitCode = failures.length === 0 ? 0 : 1;
