// The report page in a real browser (ctest: browser_report, label browser; docs/report.md, "Tests").
//
//   node tests/browser/report_page_test.mjs --cli build/bin/shatterbench --web build/web --source . \
//        --work build/browser-test --screenshots build/browser-screenshots [--chromium /usr/bin/chromium]
//
// Makes real results with the built command line (a small grid with its frames recorded, an accuracy
// run, a stability case, a fracture table with its fragments and a textured asset's fragments) and three copies of the grid (a hostile case name; synthetic per-frame stage times and
// a failed cell; no per-frame stage times, as older grids wrote), writes their report, and opens
// report.html from file:// in headless Chromium (puppeteer-core from the build folder's node_modules;
// no browser is downloaded).
// Fails on any request that is not file:, data: or blob:, on any console error, page error or dialog,
// when a chart's marks differ from the data, when a clicked heat-map cell does not open its timeline,
// when a 3D view draws too little (pixels read back) or not one mesh per fragment, when the playback
// does not reach its last frame or shows other bodies than the results count, and when the page copied alone into another folder does not open the same way. Screenshots go to
// --screenshots. Exit 0 when every check passed, 1 otherwise (a missing browser included: never a skip).

import { execFileSync } from "node:child_process";
import fs from "node:fs";
import { createRequire } from "node:module";
import os from "node:os";
import path from "node:path";
import { pathToFileURL } from "node:url";

function parseArgs(argv) {
  const args = { chromium: "/usr/bin/chromium" };
  for (let i = 0; i < argv.length; i += 2) {
    const key = argv[i].replace(/^--/, "").replace(/-([a-z])/g, (_, c) => c.toUpperCase());
    args[key] = argv[i + 1];
  }
  for (const key of ["cli", "web", "work", "screenshots", "source"]) {
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

/** Runs the command line; exit codes in `ok` are accepted (a grid over budget exits 1). */
function shatterbench(cli, args, ok = [0]) {
  try {
    execFileSync(cli, args, { stdio: ["ignore", "ignore", "pipe"] });
  } catch (error) {
    if (!ok.includes(error.status)) {
      throw new Error(`shatterbench ${args.join(" ")}: exit ${error.status}: ${String(error.stderr).trim()}`);
    }
  }
}

/** A 1 x 1 x 1 cube as OFF, for the fracture table. */
const CUBE_OFF = `OFF
8 12 0
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
3 0 2 1
3 0 3 2
3 4 5 6
3 4 6 7
3 0 1 5
3 0 5 4
3 1 2 6
3 1 6 5
3 2 3 7
3 2 7 6
3 3 0 4
3 3 4 7
`;

export const HOSTILE_NAME = "</script><script>alert(1)</script>";

/** The stages given to every frame of the copy with per-frame stage times, and their shares. */
const STAGE_SHARES = { physics: 0.7, stress: 0.2, colliders: 0.1 };

/**
 * A copy of a grid results document as a grid that records per-frame stage times would write it
 * (`samples[k].frame_stages_ms`, `worst_frame_stages_ms`), with its last cell failed (`grid --timeout`).
 */
function withFrameStages(results) {
  for (const cell of results.cells) {
    delete cell.worst_frame_stages_ms;
    for (const sample of cell.samples) {
      sample.frame_stages_ms = {};
      for (const [stage, share] of Object.entries(STAGE_SHARES)) sample.frame_stages_ms[stage] = sample.frame_ms.map((v) => v * share);
      const worst = sample.frame_ms.indexOf(Math.max(...sample.frame_ms));
      sample.worst_frame_stages_ms = Object.fromEntries(Object.entries(sample.frame_stages_ms).map(([k, v]) => [k, v[worst]]));
    }
  }
  const last = results.cells[results.cells.length - 1];
  results.cells[results.cells.length - 1] = {
    prefracture: last.prefracture, runtime: last.runtime, prefracturer: last.prefracturer, fracturer: last.fracturer,
    stress: last.stress, schedule: last.schedule, failed: "timeout after 2 s", within_budget: false,
    within_latency_budget: false, samples: [],
  };
  return results;
}

/** A copy of a grid results document as a grid from before per-frame stage times wrote it. */
function withoutFrameStages(results) {
  for (const cell of results.cells) {
    delete cell.worst_frame_stages_ms;
    for (const sample of cell.samples) {
      delete sample.frame_stages_ms;
      delete sample.worst_frame_stages_ms;
    }
  }
  return results;
}

function makeResults(cli, work, args) {
  const files = {
    grid: path.join(work, "grid.json"),
    hostile: path.join(work, "hostile-grid.json"),
    staged: path.join(work, "staged-grid.json"),
    legacy: path.join(work, "legacy-grid.json"),
    accuracy: path.join(work, "accuracy.json"),
    stability: path.join(work, "stability.json"),
    table: path.join(work, "table.json"),
    tableFragments: path.join(work, "table-fragments"),
    prefetch: path.join(work, "schedule-prefetch.json"),
    amortized: path.join(work, "schedule-amortized.json"),
    textured: path.join(work, "textured-fragments"),
  };
  shatterbench(cli, ["grid", "--case", "building", "--prefracture", "10,20", "--runtime", "5,10", "--repetitions", "2",
    "--frames", "30", "--no-cache", "--record-frames", "--json", files.grid], [0, 1]);
  for (const schedule of ["prefetch", "amortized"])
    shatterbench(cli, ["grid", "--case", "building", "--prefracture", "10", "--runtime", "5", "--repetitions", "1", "--frames", "30",
      "--no-cache", "--schedule", schedule, "--json", files[schedule]], [0, 1]);
  const hostile = JSON.parse(fs.readFileSync(files.grid, "utf8"));
  hostile.case.name = HOSTILE_NAME;
  fs.writeFileSync(files.hostile, JSON.stringify(hostile));
  fs.writeFileSync(files.staged, JSON.stringify(withFrameStages(JSON.parse(fs.readFileSync(files.grid, "utf8")))));
  fs.writeFileSync(files.legacy, JSON.stringify(withoutFrameStages(JSON.parse(fs.readFileSync(files.grid, "utf8")))));
  shatterbench(cli, ["accuracy", "--case", "cantilever", "--family", "stress", "--model", "von-mises", "connection-count",
    "--slabs", "8", "16", "--repetitions", "1", "--json", files.accuracy]);
  shatterbench(cli, ["stability", "--algo", "plane-slice", "--model", "none", "--hazard", "cut-through-vertices",
    "--timeout", "120", "--json", files.stability], [0, 1]);
  const cube = path.join(work, "cube.off");
  fs.writeFileSync(cube, CUBE_OFF);
  shatterbench(cli, ["table", "--mesh", cube, "--algo", "plane-slice", "voronoi", "--fragments", "4", "--repetitions", "1",
    "--json", files.table, "--out", files.tableFragments], [0, 1]);
  // A textured asset: its surface keeps the texture, its cut faces get the interior material.
  shatterbench(cli, ["fracture", "--mesh", path.join(args.source, "data", "assets", "BoxTextured.glb"), "--algo", "voronoi",
    "--fragments", "6", "--out", files.textured]);
  return files;
}

/** Opens `url` in a new page that records every request and fails on anything but file:, data:, blob:. */
async function openGuarded(browser, url, label) {
  const page = await browser.newPage();
  await page.setViewport({ width: 1240, height: 900 });
  const requests = [];
  await page.setRequestInterception(true);
  page.on("request", (request) => {
    const target = request.url();
    requests.push(target);
    if (/^(file|data|blob):/.test(target)) request.continue();
    else {
      failures.push(`${label}: a network request to ${target}`);
      request.abort();
    }
  });
  page.on("console", (message) => {
    if (message.type() === "error") failures.push(`${label}: console error: ${message.text()}`);
  });
  page.on("pageerror", (error) => failures.push(`${label}: page error: ${error.message}`));
  page.on("dialog", async (dialog) => {
    failures.push(`${label}: a dialog opened (${dialog.message()}): script from a results file ran`);
    await dialog.dismiss();
  });
  await page.goto(url, { waitUntil: "load" });
  await page.waitForFunction(() => document.body.dataset.ready !== undefined, { timeout: 30000 });
  const ready = await page.evaluate(() => document.body.dataset.ready);
  check(ready === "true", `${label}: the page did not draw (data-ready=${ready})`);
  return { page, requests };
}

function paretoExpectations(accuracy) {
  const groups = new Map();
  for (const p of accuracy.points) {
    const key = `${p.family}\u0000${p.case}`;
    if (!groups.has(key)) groups.set(key, { family: p.family, caseName: p.case, marks: 0, front: 0 });
    const g = groups.get(key);
    if (Number.isFinite(p.time_ms) && p.time_ms > 0 && Number.isFinite(p.error)) {
      g.marks++;
      if (p.pareto === true) g.front++;
    }
  }
  return [...groups.values()];
}

async function checkReport(page, files) {
  const grid = JSON.parse(fs.readFileSync(files.grid, "utf8"));
  const accuracy = JSON.parse(fs.readFileSync(files.accuracy, "utf8"));
  const stability = JSON.parse(fs.readFileSync(files.stability, "utf8"));
  const table = JSON.parse(fs.readFileSync(files.table, "utf8"));

  // One heat map per grid file, one mark per cell (a failed cell included, labelled).
  const maps = await page.$$eval('[data-chart="heat-map"]', (els) => els.map((e) => ({
    marks: Number(e.dataset.marks), buttons: e.querySelectorAll(".heat-cell").length,
    failed: e.querySelectorAll(".heat-cell.failed").length })));
  check(maps.length === 6, `heat maps: expected 6 (grid, hostile copy, copies with and without stages, two schedules), found ${maps.length}`);
  for (const m of maps.slice(0, 4)) {
    check(m.marks === grid.cells.length, `heat map: data-marks ${m.marks}, the grid has ${grid.cells.length} cells`);
    check(m.buttons === grid.cells.length, `heat map: ${m.buttons} cells drawn, the grid has ${grid.cells.length}`);
  }
  check(maps.map((m) => m.failed).join(",") === "0,0,1,0,0,0", `failed cells drawn: ${maps.map((m) => m.failed)}, expected 0,0,1,0,0,0`);

  // The schedules side by side: building's 10 x 5 cell ran immediate (the grid), prefetch and amortized.
  const schedules = await page.$$eval('[data-chart="schedules"]', (els) => els.map((e) => ({ cell: e.dataset.cell, marks: Number(e.dataset.marks),
    rows: Number(e.querySelector('[data-table="schedules"]').dataset.rows), canvas: e.querySelectorAll("canvas").length })));
  check(schedules.length === 1 && schedules[0].cell === "10 x 5" && schedules[0].marks === 3 && schedules[0].rows === 3 && schedules[0].canvas > 0,
    `schedules side by side: ${JSON.stringify(schedules)}, expected one view of cell 10 x 5 with 3 schedules`);

  // The hostile case name is text, and the only scripts are the page's two.
  const headings = await page.$$eval('[data-section="grid"] h2', (els) => els.map((e) => e.textContent));
  check(headings.some((h) => h.includes(HOSTILE_NAME)), `the hostile case name is not shown as text: ${JSON.stringify(headings)}`);
  const scripts = await page.$$eval("script", (els) => els.length);
  check(scripts === 2, `scripts in the page: expected 2 (data and bundle), found ${scripts}`);

  // Pareto charts: one per family and case, one mark per point, front marks per front point.
  const expected = paretoExpectations(accuracy);
  const charts = await page.$$eval('[data-chart="pareto"]', (els) => els.map((e) => ({
    family: e.dataset.family, caseName: e.dataset.case, marks: Number(e.dataset.marks),
    front: Number(e.dataset.frontMarks), canvas: e.querySelectorAll("canvas").length })));
  check(charts.length === expected.length, `Pareto charts: expected ${expected.length}, found ${charts.length}`);
  for (const want of expected) {
    const got = charts.find((c) => c.family === want.family && c.caseName === want.caseName);
    check(got !== undefined, `no Pareto chart for ${want.family} ${want.caseName}`);
    if (!got) continue;
    check(got.marks === want.marks, `Pareto ${want.family} ${want.caseName}: ${got.marks} marks, ${want.marks} points`);
    check(got.front === want.front, `Pareto ${want.family} ${want.caseName}: ${got.front} front marks, ${want.front} front points`);
    check(got.marks === 0 || got.canvas > 0, `Pareto ${want.family} ${want.caseName}: no canvas drawn`);
  }
  check(expected.some((g) => g.marks > 0 && g.front > 0), "the accuracy run gave no point with an error to draw");

  // The tables: one row per verdict and per run.
  const stabilityRows = await page.$eval('[data-table="stability"]', (e) => Number(e.dataset.rows));
  check(stabilityRows === stability.results.length, `stability table: ${stabilityRows} rows, ${stability.results.length} verdicts`);
  const tableRows = await page.$eval('[data-table="table-runs"]', (e) => Number(e.dataset.rows));
  check(tableRows === table.rows.length, `table runs: ${tableRows} rows, ${table.rows.length} in the file`);

  // Hover shows the value.
  const firstCell = (await page.$$('[data-chart="heat-map"] .heat-cell'))[0];
  await firstCell.hover();
  const readout = await page.$eval('[data-chart="heat-map"] .readout', (e) => e.textContent);
  check(/worst frame .* ms/.test(readout), `hovering a heat-map cell shows no value: "${readout}"`);

  // A click on another cell opens its timeline.
  const shown = await page.$eval('[data-chart="timeline"]', (e) => e.dataset.cell);
  const target = grid.cells.find((c) => `${c.prefracture} x ${c.runtime}` !== shown);
  await page.click(`[data-chart="heat-map"] .heat-cell[data-prefracture="${target.prefracture}"][data-runtime="${target.runtime}"]`);
  const label = `${target.prefracture} x ${target.runtime}`;
  await page.waitForFunction((l) => document.querySelector('[data-chart="timeline"]').dataset.cell === l, { timeout: 5000 }, label);
  const timeline = await page.$eval('[data-chart="timeline"]', (e) => ({
    title: e.querySelector(".chart-title").textContent, marks: Number(e.dataset.marks), frames: Number(e.dataset.frames),
    eventFrame: Number(e.dataset.eventFrame), stacked: Number(e.dataset.stackedStages),
    canvas: e.querySelectorAll("canvas").length }));
  check(timeline.title.includes(`Cell ${label}`), `the timeline's title does not name cell ${label}: "${timeline.title}"`);
  check(timeline.marks === grid.repetitions, `timeline: ${timeline.marks} lines, ${grid.repetitions} repetitions`);
  check(timeline.frames === grid.frames, `timeline: ${timeline.frames} frames, the grid ran ${grid.frames}`);
  check(timeline.eventFrame === target.samples[0].event_frame, `timeline: event frame ${timeline.eventFrame}, the results say ${target.samples[0].event_frame}`);
  check(timeline.canvas > 0, "timeline: no canvas drawn");
  await page.click('[data-chart="timeline"] [data-action="fit-frames"]');
  const yScale = await page.$eval('[data-chart="timeline"]', (e) => e.dataset.yScale);
  check(yScale === "frames", `timeline: "Zoom to the frames" left the y axis at "${yScale}"`);
  const stageViews = await page.$$eval('.cell-detail [data-chart="worst-frame-stages"], .cell-detail [data-chart="stage-totals"]',
    (els) => els.map((e) => ({ kind: e.dataset.chart, marks: Number(e.dataset.marks) })));
  const totals = stageViews.find((v) => v.kind === "stage-totals");
  check(stageViews.some((v) => v.kind === "worst-frame-stages"), "no worst-frame stage view for the chosen cell");
  check(totals && totals.marks === Object.keys(target.stages_ms).length,
    `stage totals: ${totals ? totals.marks : "no"} bars, the cell has ${Object.keys(target.stages_ms).length} stages`);
  const recorded = Object.values(target.samples[0].frame_stages_ms || {})
    .filter((v) => Array.isArray(v) && v.length === grid.frames && v.some((x) => x > 0)).length;
  check(timeline.stacked === recorded, `timeline: ${timeline.stacked} stacked stages, the first repetition records ${recorded}`);

  // The copy from before per-frame stage times: no stacked stages, and the worst frame's stages unrecorded.
  const legacy = `section[data-file="${files.legacy}"]`;
  await page.click(`${legacy} .heat-cell[data-prefracture="${target.prefracture}"][data-runtime="${target.runtime}"]`);
  const legacyView = await page.$eval(legacy, (section) => ({
    stacked: Number(section.querySelector('[data-chart="timeline"]').dataset.stackedStages),
    worst: section.querySelector('[data-chart="worst-frame-stages"]').dataset.recorded }));
  check(legacyView.stacked === 0, `results without stage times per frame: ${legacyView.stacked} stacked stages`);
  check(legacyView.worst === "false", "results without stage times per frame: the worst frame's stages are not said to be unrecorded");

  // The copy with per-frame stage times: stacked stages under the lines, the worst frame by stage.
  const staged = `section[data-file="${files.staged}"]`;
  await page.click(`${staged} .heat-cell[data-prefracture="${grid.cells[0].prefracture}"][data-runtime="${grid.cells[0].runtime}"]`);
  const stages = Object.keys(STAGE_SHARES).length;
  const stagedView = await page.$eval(staged, (section) => {
    const t = section.querySelector('[data-chart="timeline"]');
    const w = section.querySelector('[data-chart="worst-frame-stages"]');
    return { cell: t.dataset.cell, stacked: Number(t.dataset.stackedStages), worst: Number(w.dataset.marks) };
  });
  check(stagedView.cell === `${grid.cells[0].prefracture} x ${grid.cells[0].runtime}`, `stages copy: timeline of ${stagedView.cell}`);
  check(stagedView.stacked === stages, `stages copy: ${stagedView.stacked} stacked stages, the results have ${stages}`);
  check(stagedView.worst === stages, `stages copy: ${stagedView.worst} worst-frame bars, the results have ${stages}`);
  const failedCell = grid.cells[grid.cells.length - 1];
  await page.click(`${staged} .heat-cell[data-prefracture="${failedCell.prefracture}"][data-runtime="${failedCell.runtime}"]`);
  const failedText = await page.$eval(`${staged} [data-chart="timeline"]`, (t) => t.textContent);
  check(failedText.includes("timeout after 2 s"), `a failed cell's timeline does not give its reason: "${failedText}"`);
}

/** Share of the canvas `selector` whose pixels differ from the 3D views' background, the box they span and the share of it they fill. */
async function drawnShare(page, selector) {
  return page.$eval(selector, (canvas) => {
    const { width, height } = canvas;
    const pixels = canvas.getContext("2d").getImageData(0, 0, width, height).data;
    const background = [0xf1, 0xf3, 0xf5];
    let drawn = 0, minX = width, maxX = -1, minY = height, maxY = -1;
    for (let y = 0; y < height; y++) {
      for (let x = 0; x < width; x++) {
        const i = 4 * (y * width + x);
        if (Math.abs(pixels[i] - background[0]) + Math.abs(pixels[i + 1] - background[1]) + Math.abs(pixels[i + 2] - background[2]) > 24) {
          drawn++;
          minX = Math.min(minX, x); maxX = Math.max(maxX, x); minY = Math.min(minY, y); maxY = Math.max(maxY, y);
        }
      }
    }
    const area = maxX < 0 ? 0 : (maxX - minX + 1) * (maxY - minY + 1);
    return { share: drawn / (width * height), area, fill: area > 0 ? drawn / area : 0 };
  });
}

/** Every fragments folder below `dir` (its fracture.json), as the report finds them. */
function fragmentsFolders(dir) {
  if (fs.existsSync(path.join(dir, "fracture.json"))) return [dir];
  return fs.readdirSync(dir, { withFileTypes: true }).filter((e) => e.isDirectory()).flatMap((e) => fragmentsFolders(path.join(dir, e.name)));
}

/** The 3D fragments views and the playback of the recorded grid. */
async function check3D(page, files, screenshots) {
  await page.waitForFunction(() => document.body.dataset.drawn !== undefined, { timeout: 120000 });
  check(await page.evaluate(() => document.body.dataset.drawn) === "true", "the 3D views did not all draw");

  // One panel per fragments folder, one mesh per fragment, the fragments' volumes adding up to the cube's.
  const folders = [...fragmentsFolders(files.tableFragments), files.textured].map((f) => JSON.parse(fs.readFileSync(path.join(f, "fracture.json"), "utf8")));
  const panels = await page.$$eval('[data-view="fragments"]', (els) => els.map((e) => ({ ...e.dataset })));
  check(panels.length === folders.length, `fragments panels: ${panels.length}, folders: ${folders.length}`);
  for (const summary of folders) {
    const panel = panels.find((p) => p.algorithm === summary.algorithm && Number(p.fragments) === summary.fragments);
    check(panel !== undefined, `no fragments panel for ${summary.algorithm} (${summary.fragments} fragments)`);
    if (!panel) continue;
    check(panel.ready === "true", `fragments panel ${summary.algorithm}: not drawn`);
    check(Number(panel.meshes) === summary.fragments, `fragments panel ${summary.algorithm}: ${panel.meshes} meshes for ${summary.fragments} fragments`);
  }
  const cubePanels = panels.filter((p) => !/Textured/.test(p.title || ""));
  for (const p of cubePanels) check(Math.abs(Number(p.totalVolume) - 1) < 1e-6, `the ${p.algorithm} fragments of the unit cube hold ${p.totalVolume} m^3`);
  const canvases = await page.$$('[data-view="fragments"] canvas.view3d');
  check(canvases.length === folders.length, `fragments canvases: ${canvases.length}`);
  const shares = await page.$$eval('[data-view="fragments"] canvas.view3d', (els) => els.map((c) => c.dataset.drawn));
  check(shares.every((n) => Number(n) >= 1), `fragments canvases not drawn: ${JSON.stringify(shares)}`);
  const first = '[data-section="fragments"] [data-view="fragments"] canvas.view3d';
  const before = await drawnShare(page, first);
  check(before.share > 0.05, `the first fragments view is ${(100 * before.share).toFixed(1)} % drawn, expected more than 5 %`);

  // The explode slider spreads the fragments: gaps open between them, so less of the box they span is drawn.
  await page.$eval('[data-section="fragments"] [data-control="explode"]', (s) => { s.value = "100"; s.dispatchEvent(new Event("input")); });
  const after = await drawnShare(page, first);
  check(after.fill < before.fill * 0.9 && after.share > 0.01,
    `explode: ${(100 * before.fill).toFixed(1)} % of the fragments' box drawn at rest, ${(100 * after.fill).toFixed(1)} % exploded`);
  await (await page.$('[data-section="fragments"]')).screenshot({ path: path.join(screenshots, "report-fragments.png") });
  await page.$eval('[data-section="fragments"] [data-control="explode"]', (s) => { s.value = "0"; s.dispatchEvent(new Event("input")); });

  // Hover: the fragment under the pointer and its volume.
  const box = await (await page.$(first)).boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  const hover = await page.$eval('[data-section="fragments"] [data-view="fragments"] .hover-line', (e) => ({ text: e.textContent, name: e.dataset.hover }));
  check(/^fragment_\d+$/.test(hover.name) && /volume [0-9.e-]+ m/.test(hover.text), `hovering a fragment shows no volume: "${hover.text}"`);

  // Playback of the recorded cell: reaches the last frame; a click on the timeline's spike frame shows it.
  const grid = JSON.parse(fs.readFileSync(files.grid, "utf8"));
  const section = `section[data-file="${files.grid}"]`;
  const shown = await page.$eval(`${section} [data-chart="timeline"]`, (e) => e.dataset.cell);
  const cell = grid.cells.find((c) => `${c.prefracture} x ${c.runtime}` === shown);
  const recording = grid.recorded_frames.recordings.find((r) => r.prefracture === cell.prefracture && r.runtime === cell.runtime);
  const sample = cell.samples[recording.repetition];
  const player = `${section} [data-view="playback"]`;
  await page.waitForSelector(`${player}[data-ready="true"]`, { timeout: 30000 });
  const info = await page.$eval(player, (e) => ({ ...e.dataset }));
  check(Number(info.frames) === grid.frames, `playback: ${info.frames} frames, the grid ran ${grid.frames}`);
  check(Number(info.bodies) === recording.bodies, `playback: ${info.bodies} bodies, the results say ${recording.bodies}`);
  check(Number(info.frame) === Math.max(0, sample.event_frame), `playback opens at frame ${info.frame}, the event frame is ${sample.event_frame}`);
  await page.click(`${player} [data-action="play"]`);
  await page.waitForSelector(`${player}[data-reached-end="true"]`, { timeout: 30000 });
  const end = await page.$eval(player, (e) => ({ ...e.dataset }));
  check(Number(end.frame) === grid.frames - 1, `playback stopped at frame ${end.frame}`);
  check(Number(end.present) === sample.bodies && Number(end.shown) === sample.bodies,
    `playback: ${end.present} bodies present and ${end.shown} drawn at the last frame, the results say ${sample.bodies}`);
  const sweep = await page.$eval(player, (fig) => {
    const s = fig.querySelector('[data-control="scrubber"]');
    let spawned = 0, peak = 0;
    for (let f = 0; f < Number(fig.dataset.frames); f++) {
      s.value = String(f);
      s.dispatchEvent(new Event("input"));
      spawned += Number(fig.dataset.spawned);
      peak = Math.max(peak, Number(fig.dataset.present));
    }
    return { spawned, peak };
  });
  check(sweep.peak === sample.bodies_peak, `playback: at most ${sweep.peak} bodies in a frame, the results say ${sample.bodies_peak}`);
  check(sweep.spawned === recording.bodies, `playback: ${sweep.spawned} bodies entered over the frames, ${recording.bodies} were recorded`);
  const spike = sample.frame_ms.indexOf(Math.max(...sample.frame_ms));
  const over = await (await page.$(`${section} [data-chart="timeline"] .u-over`)).boundingBox();
  await page.mouse.click(over.x + (over.width * spike) / (grid.frames - 1), over.y + over.height / 2);
  const atSpike = await page.$eval(player, (e) => ({ ...e.dataset }));
  const playhead = await page.$eval(`${section} [data-chart="timeline"]`, (e) => e.dataset.playhead);
  check(Number(atSpike.frame) === spike && Number(playhead) === spike, `a click on the spike frame ${spike} shows frame ${atSpike.frame} (playhead ${playhead})`);
  check(Number(atSpike.shown) === Number(atSpike.present) && Number(atSpike.present) <= sample.bodies_peak && Number(atSpike.present) > 0,
    `the spike frame draws ${atSpike.shown} bodies, ${atSpike.present} were present, at most ${sample.bodies_peak}`);
  const drawn = await drawnShare(page, `${player} canvas.view3d`);
  check(drawn.share > 0.02, `the playback is ${(100 * drawn.share).toFixed(1)} % drawn at the spike frame`);
  await (await page.$(`${section} .cell-detail`)).screenshot({ path: path.join(screenshots, "report-playback.png") });
}

async function main() {
  const args = parseArgs(process.argv.slice(2));
  if (!fs.existsSync(args.chromium)) {
    throw new Error(`no browser at ${args.chromium}: install Debian's chromium (scripts/install-deps)`);
  }
  const require = createRequire(path.join(path.resolve(args.web), "package.json"));
  const puppeteer = require("puppeteer-core");

  const work = path.resolve(args.work);
  fs.rmSync(work, { recursive: true, force: true });
  fs.mkdirSync(work, { recursive: true });
  fs.mkdirSync(args.screenshots, { recursive: true });
  const files = makeResults(args.cli, work, args);
  const out = path.join(work, "report");
  execFileSync(args.cli, ["report", files.grid, files.hostile, files.staged, files.legacy, files.accuracy, files.stability,
    files.table, files.tableFragments, files.textured, files.prefetch, files.amortized, "--out", out],
    { stdio: ["ignore", "ignore", "inherit"] });
  const reportFile = path.join(out, "report.html");

  const browser = await puppeteer.launch({
    executablePath: args.chromium,
    headless: true,
    args: ["--headless=new", "--no-sandbox", "--enable-unsafe-swiftshader", "--use-angle=swiftshader"],
  });
  try {
    const url = pathToFileURL(reportFile).href;
    const { page, requests } = await openGuarded(browser, url, "report.html");
    await page.screenshot({ path: path.join(args.screenshots, "report-top.png") });
    await checkReport(page, files);
    await check3D(page, files, args.screenshots);
    const detail = await page.$(".cell-detail");
    await detail.screenshot({ path: path.join(args.screenshots, "report-cell-timeline.png") });
    const pareto = await page.$('[data-chart="pareto"]');
    await pareto.screenshot({ path: path.join(args.screenshots, "report-pareto.png") });
    await page.screenshot({ path: path.join(args.screenshots, "report-full.png"), fullPage: true });
    const loaded = requests.filter((r) => !/^(data|blob):/.test(r));
    check(loaded.length === 1 && loaded[0] === url, `report.html loaded more than itself: ${JSON.stringify(loaded)}`);
    await page.close();

    // The page alone, copied into another folder (no results files, no images beside it).
    const elsewhere = fs.mkdtempSync(path.join(os.tmpdir(), "shatterbench-report-copy-"));
    try {
      const copy = path.join(elsewhere, "copied-report.html");
      fs.copyFileSync(reportFile, copy);
      const copyUrl = pathToFileURL(copy).href;
      const opened = await openGuarded(browser, copyUrl, "copied report.html");
      const marks = await opened.page.$$eval('[data-chart="heat-map"]', (els) => els.map((e) => Number(e.dataset.marks)));
      check(marks.length === 6 && marks.every((m) => m > 0), `the copied page drew no heat map: ${JSON.stringify(marks)}`);
      const copyLoaded = opened.requests.filter((r) => !/^(data|blob):/.test(r));
      check(copyLoaded.length === 1 && copyLoaded[0] === copyUrl, `the copied page loaded more than itself: ${JSON.stringify(copyLoaded)}`);
      await opened.page.waitForFunction(() => document.body.dataset.drawn !== undefined, { timeout: 60000 });
      const copyPanels = await opened.page.$$eval('[data-view="fragments"]', (els) => els.map((e) => e.dataset.ready));
      check(copyPanels.length > 0 && copyPanels.every((r) => r === "true"), `the copied page drew no fragments: ${JSON.stringify(copyPanels)}`);
      await opened.page.close();
    } finally {
      fs.rmSync(elsewhere, { recursive: true, force: true });
    }
  } finally {
    await browser.close();
  }
}

try {
  await main();
} catch (error) {
  failures.push(`error: ${error && error.stack ? error.stack : error}`);
}
for (const f of failures) console.error(`browser_report: FAILED: ${f}`);
console.log(`browser_report: ${passed} passed, ${failures.length} failed`);
process.exitCode = failures.length === 0 ? 0 : 1;
