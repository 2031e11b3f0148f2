// Opens report pages in headless Chromium and times each from navigation to drawn (every view, the 3D
// ones included: the page sets body[data-drawn]), a fresh page per sample. Prints one benchmark row per
// page: its size and the median, min and max of the samples. A benchmark, not a test: it asserts nothing.
//
//   node benchmarks/browser/page_open_benchmark.mjs --web build/web [--chromium /usr/bin/chromium] \
//        [--samples 5] PAGE.html...

import fs from "node:fs";
import { createRequire } from "node:module";
import path from "node:path";
import { pathToFileURL } from "node:url";

const args = { chromium: "/usr/bin/chromium", samples: "5", pages: [] };
const argv = process.argv.slice(2);
for (let i = 0; i < argv.length; i++) {
  if (argv[i].startsWith("--")) args[argv[i].slice(2)] = argv[++i];
  else args.pages.push(argv[i]);
}
if (!args.web || args.pages.length === 0) {
  console.error("page_open_benchmark: usage: --web BUILD/web [--chromium PATH] [--samples N] PAGE.html...");
  process.exit(2);
}
const puppeteer = createRequire(path.join(path.resolve(args.web), "package.json"))("puppeteer-core");
const browser = await puppeteer.launch({
  executablePath: args.chromium,
  headless: true,
  args: ["--headless=new", "--no-sandbox", "--enable-unsafe-swiftshader", "--use-angle=swiftshader"],
});
const median = (v) => { const s = [...v].sort((a, b) => a - b); const n = s.length; return n % 2 ? s[(n - 1) / 2] : (s[n / 2 - 1] + s[n / 2]) / 2; };
try {
  for (const file of args.pages) {
    const url = pathToFileURL(path.resolve(file)).href;
    const samples = [];
    for (let k = 0; k < Number(args.samples); k++) {
      const page = await browser.newPage();
      await page.setViewport({ width: 1240, height: 900 });
      const start = performance.now();
      await page.goto(url, { waitUntil: "load" });
      await page.waitForFunction(() => document.body.dataset.drawn !== undefined, { timeout: 120000, polling: 10 });
      samples.push(performance.now() - start);
      const drawn = await page.evaluate(() => document.body.dataset.drawn);
      await page.close();
      if (drawn !== "true") throw new Error(`${file}: the page did not draw (data-drawn=${drawn})`);
    }
    const mb = fs.statSync(file).size / 1e6;
    console.log(`page_open/${path.basename(file)}  ${mb.toFixed(2)} MB  median ${(median(samples) / 1000).toFixed(2)} s  `
      + `min ${(Math.min(...samples) / 1000).toFixed(2)} s  max ${(Math.max(...samples) / 1000).toFixed(2)} s  (${samples.length} samples, headless Chromium)`);
  }
} finally {
  await browser.close();
}
