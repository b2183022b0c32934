// The report's periodic-orbits section (docs/report.md): registered under "orbits" and
// drawn by the report's script (src/io/report/report.js) from data.orbits, the
// section's data feran embedded.
(window.feranSections = window.feranSections || {}).orbits = function (report) {
  "use strict";
  const { data, unit, fromHz, speedTitle, numbers, palette, sectionEl, failed, figure, axis, table, fmt } = report;
  if (!data.orbits) return;
  const s = sectionEl("orbits", "Periodic orbits", "Steady states by harmonic balance continued over the range: the equilibrium, the orbits the unbalance forces and the self-excited whirl, each with its Floquet stability (solid: stable, dashed: unstable) and the bifurcations located on it (■ fold, ● Hopf, ◆ Neimark–Sacker, ▲ period doubling). Amplitude: the largest distance of the orbit from its centre.");
  const o = data.orbits;
  if (o.error) {
    failed(s, "orbits");
    return;
  }
  const bySpeed = o.parameter.path === "speed";
  const x = (p) => (bySpeed ? fromHz(p.speed_hz) : p.parameter);
  const xTitle = bySpeed ? speedTitle : `${o.parameter.path} [${o.parameter.unit}]`;
  const markers = { fold: "square-open", hopf: "circle-open", neimark_sacker: "diamond-open", period_doubling: "triangle-up-open", static_instability: "triangle-down-open" };
  o.probes.forEach((probe, i) => {
    const traces = [];
    o.branches.forEach((b, n) => {
      const colour = palette[n % palette.length];
      // Stable and unstable stretches as two traces, each gap a null, so the dashes
      // follow the states' stability.
      for (const stable of [true, false]) {
        const xs = [], ys = [];
        b.points.forEach((p, k) => {
          const next = b.points[k + 1];
          if (p.stable === stable || (next && next.stable === stable)) {
            xs.push(x(p));
            ys.push(p.probes[i].amplitude_m * 1e6);
          } else if (xs.length && xs[xs.length - 1] !== null) {
            xs.push(null);
            ys.push(null);
          }
        });
        traces.push({ name: `${b.name}${stable ? "" : " (unstable)"}`, x: xs, y: ys, mode: "lines", line: { color: colour, dash: stable ? "solid" : "dash" } });
      }
      if (b.bifurcations.length)
        traces.push({ name: `${b.name}: bifurcations`, x: b.bifurcations.map(x), y: b.bifurcations.map((f) => f.probes[i].amplitude_m * 1e6), text: b.bifurcations.map((f) => f.kind.replace("_", " ")),
                      mode: "markers+text", textposition: "top right", marker: { color: "black", size: 10, symbol: b.bifurcations.map((f) => markers[f.kind] || "x") } });
    });
    figure(s, traces, { title: { text: `steady states at ${probe.name || "node " + probe.node}` }, xaxis: axis(xTitle), yaxis: axis("amplitude [µm]"), height: 420 });
  });
  const rows = [];
  // The run that found the first orbit (start_at): where, when it settled, its frequency.
  if (o.run) rows.push(["run (start)", `settled after ${fmt(o.run.settled_after_s, 3)} s`, bySpeed ? `${fmt(fromHz(o.run.speed_hz), 5)} ${unit}` : `${fmt(o.run.parameter, 5)} ${o.parameter.unit}`, `${fmt(o.run.frequency_hz, 5)} Hz`, ""]);
  o.branches.forEach((b) => {
    b.bifurcations.forEach((f) => {
      const where = bySpeed ? `${fmt(fromHz(f.speed_hz), 5)} ${unit}` : `${fmt(f.parameter, 5)} ${o.parameter.unit}`;
      rows.push([b.name, f.kind.replace("_", " "), where, f.critical_frequency_hz > 0 ? `${fmt(f.critical_frequency_hz, 5)} Hz` : "", b.criticality || ""]);
      if (bySpeed) numbers.push([`${f.kind.replace("_", " ")} on ${b.name}`, fromHz(f.speed_hz), unit, "orbits"]);
    });
    const last = b.points[b.points.length - 1];
    if (last) rows.push([b.name, b.clipped ? "range's end" : `ended: ${b.ended_by}`, bySpeed ? `${fmt(fromHz(last.speed_hz), 5)} ${unit}` : `${fmt(last.parameter, 5)} ${o.parameter.unit}`, "", ""]);
  });
  table(s, ["branch", "event", "at", "growing motion", "criticality"], rows);
};
