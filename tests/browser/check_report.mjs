// Opens a feran report in Debian's Chromium (headless, driven by playwright-core)
// with every network request refused, and checks what a reader would see: no
// JavaScript error or failed request, every section of the report's data drawn, each
// figure with the traces and axis titles that section must have (the rules below,
// from what each analysis's JSON holds), and a screenshot of the whole page.
//
// node tests/browser/check_report.mjs REPORT.html PREFIX SECTIONS [REPORT.html PREFIX SECTIONS ...]
// checks each report in turn, in one browser, and writes PREFIX.png
// (the whole page) and, with FERAN_SECTION_SCREENSHOTS=1, PREFIX-SECTION.png (each
// section). SECTIONS: the sections that must be present, comma-separated (model,
// campbell, damping, modes, response, static, api684, runup, orbits, study, numbers).
// Exit code 0 when all is well.
import { chromium } from "playwright-core";

const args = process.argv.slice(2);
if (args.length === 0 || args.length % 3 !== 0) {
  console.error("usage: node check_report.mjs REPORT.html PREFIX SECTIONS [REPORT.html PREFIX SECTIONS ...]");
  process.exit(2);
}
const problems = [];
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
  args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--use-angle=swiftshader", "--enable-unsafe-swiftshader"],
});
async function check(report, prefix, required) {
  const screenshot = `${prefix}.png`;
  const problem = (p) => problems.push(`${report}: ${p}`);
  const context = await browser.newContext({ offline: true, viewport: { width: 1280, height: 900 } });
  const page = await context.newPage();
  // Only the report itself may load: anything else is a request to the network.
  await page.route("**/*", (route) => {
    if (route.request().url().startsWith("file://")) return route.continue();
    problem(`network request: ${route.request().url()}`);
    return route.abort();
  });
  page.on("pageerror", (e) => problem(`JavaScript error: ${e.message}`));
  page.on("console", (m) => { if (m.type() === "error") problem(`console error: ${m.text()}`); });
  page.on("requestfailed", (r) => { if (!r.url().startsWith("file://")) problem(`failed request: ${r.url()}`); });
  await page.goto(new URL(report, `file://${process.cwd()}/`).href, { waitUntil: "load", timeout: 120000 });
  await page.waitForFunction(() => window.feranReport && window.feranReport.ready, null, { timeout: 60000 });

  const found = await page.evaluate(() => {
    const data = JSON.parse(document.getElementById("feran-data").textContent);
    const titles = (gd) => {
      const l = gd._fullLayout;
      const out = [];
      for (const k of Object.keys(l)) {
        if (/^[xy]axis\d*$/.test(k) && l[k].title && l[k].title.text) out.push(l[k].title.text);
        if (/^scene\d*$/.test(k)) for (const a of ["xaxis", "yaxis", "zaxis"]) if (l[k][a].title && l[k][a].title.text) out.push(l[k][a].title.text);
        if (/^polar\d*$/.test(k) && l[k].radialaxis.title && l[k].radialaxis.title.text) out.push(l[k].radialaxis.title.text);
      }
      return out;
    };
    const plots = window.feranReport.plots.map((p) => {
      const gd = document.getElementById(p.id);
      return { section: p.section, title: gd.layout.title ? gd.layout.title.text : "", traces: gd.data.length,
               types: gd.data.map((t) => t.type || "scatter"), axes: titles(gd),
               drawn: gd.querySelectorAll(".main-svg, canvas").length > 0 };
    });
    const sections = [...document.querySelectorAll("section")].map((s) => s.id);
    const errors = [...document.querySelectorAll(".error")].map((e) => e.textContent);
    const lateral = data.campbell.modes.filter((m) => m.type !== "axial" && m.type !== "torsional").length;
    return { plots, sections, errors, lateral, orders: data.campbell.orders.length,
             probes: data.response && data.response.probes ? data.response.probes.length : 0,
             peaks: !!(data.response && data.response.peaks),
             cases: data.api684 && data.api684.cases ? data.api684.cases.map((c) => c.probes.length) : [],
             map: data.api684 && data.api684.map ? data.api684.map.criticals_rpm.length + data.api684.map.curves.length + 1 : 0,
             modeSpeeds: data.modes.length, numbers: window.feranReport.numbers,
             runupProbes: data.runup && data.runup.probes ? data.runup.probes.length : 0,
             orbitProbes: data.orbits && data.orbits.probes ? data.orbits.probes.length : 0,
             orbitTraces: data.orbits && data.orbits.branches
               ? data.orbits.branches.reduce((n, b) => n + 2 + (b.bifurcations.length ? 1 : 0), 0) : 0,
             orbitRun: !!(data.orbits && data.orbits.run),
             orbitRunRow: [...document.querySelectorAll("section#orbits tr")].some((tr) => tr.textContent.startsWith("run (start)")) };
  });

  for (const s of required) if (!found.sections.includes(s)) problem(`section '${s}' is missing`);
  for (const e of found.errors) problem(`the report shows an error: ${e}`);
  const inSection = (s) => found.plots.filter((p) => p.section === s);
  const expect = (cond, what) => { if (!cond) problem(what); };
  for (const p of found.plots) {
    expect(p.drawn, `${p.section}: '${p.title}' was not drawn`);
    expect(p.traces > 0, `${p.section}: '${p.title}' has no trace`);
    // Parallel coordinates label their own axes; a polar plot has one radial axis; others two.
    const axesNeeded = p.types.includes("parcoords") ? 0 : p.types.includes("scatterpolar") ? 1 : 2;
    expect(p.axes.length >= axesNeeded,
           `${p.section}: '${p.title}' lacks axis titles (${p.axes.join(", ")})`);
  }
  // The rules: what each section's figures must hold.
  const campbell = inSection("campbell");
  expect(campbell.length === 1 && campbell[0].traces === found.lateral + found.orders + 1,
         `campbell: expected one figure with ${found.lateral} modes + ${found.orders} orders + the critical speeds`);
  const damping = inSection("damping");
  expect(damping.length === 1 && damping[0].traces === found.lateral, `damping: expected ${found.lateral} traces`);
  const modes = inSection("modes");
  expect(modes.length === 2 * found.modeSpeeds, `modes: expected a 3D and a 2D figure at each of ${found.modeSpeeds} speeds`);
  expect(modes.filter((p) => p.types.includes("scatter3d")).length === found.modeSpeeds, "modes: a 3D figure per speed");
  if (found.sections.includes("response")) {
    const r = inSection("response");
    // The amplitude figure has one more trace, the judged peaks, when there is an operating range.
    expect(r.length >= 3 && r[0].traces === found.probes + (found.peaks ? 1 : 0) && r[1].traces === found.probes &&
           r[2].traces === found.probes, `response: Bode amplitude, phase and polar figures with ${found.probes} probes each`);
  }
  if (found.sections.includes("api684")) {
    const a = inSection("api684");
    found.cases.forEach((n, i) => expect(a[i] && a[i].traces === n + 1, `api684: case ${i + 1} with ${n} probes and its peaks`));
    if (found.map) expect(a.some((p) => p.traces === found.map && p.title.includes("map")), `api684: the critical speed map with ${found.map} traces`);
  }
  if (found.sections.includes("runup")) {
    const r = inSection("runup");
    expect(r.length === 3 && r[0].traces === found.runupProbes && r[2].types[0] === "heatmap", "runup: envelope, time history and waterfall");
  }
  if (found.sections.includes("orbits")) {
    // Per probe a bifurcation diagram: per branch its stable and its unstable stretch, and its bifurcations.
    const o = inSection("orbits");
    expect(o.length === found.orbitProbes && o.every((p) => p.traces === found.orbitTraces),
           `orbits: a bifurcation diagram per probe (${found.orbitProbes}) with ${found.orbitTraces} traces`);
    // A branch from a run (start_at): the table says where the run settled.
    expect(found.orbitRun === found.orbitRunRow, `orbits: the run ${found.orbitRun ? "has no" : "has a"} row in the table`);
  }
  if (found.sections.includes("study")) expect(inSection("study").length >= 1, "study: at least one figure");
  expect(found.numbers > 0, "numbers: the table is empty");

  await page.screenshot({ path: screenshot, fullPage: true });
  // With FERAN_SECTION_SCREENSHOTS=1 (scripts/report_figures.sh), one per section too.
  if (process.env.FERAN_SECTION_SCREENSHOTS === "1")
    for (const id of found.sections) await page.locator(`section#${id}`).screenshot({ path: `${prefix}-${id}.png` });
  console.log(`${report}: ${found.sections.length} sections (${found.sections.join(", ")}), ${found.plots.length} figures, ` +
              `${found.plots.reduce((n, p) => n + p.traces, 0)} traces, ${found.numbers} numbers; screenshot ${screenshot}`);
  await context.close();
}

try {
  // One after the other: drawing a report keeps a core busy for seconds, and pages
  // side by side on two cores only wait for each other.
  for (let i = 0; i < args.length; i += 3) await check(args[i], args[i + 1], args[i + 2].split(",").filter((x) => x));
} finally {
  await browser.close();
}
if (problems.length) {
  for (const p of problems) console.error(`problem: ${p}`);
  process.exit(1);
}
