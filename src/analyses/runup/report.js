// The report's run-up section (docs/report.md): registered under "runup" and drawn by
// the report's script (src/io/report/report.js) from data.runup, the section's data
// feran embedded.
(window.feranSections = window.feranSections || {}).runup = function (report) {
  "use strict";
  const { data, unit, fromHz, speedTitle, numbers, palette, sectionEl, failed, figure, axis, operatingShape } = report;
  if (data.runup) {
    const s = sectionEl("runup", "Run-up", "Transient run along the speed profile: the envelope of the displacement against speed, the time history and a waterfall (amplitude spectra of v over windows of a twentieth of the run, half overlapping, each Hann-tapered with its mean removed, against speed, in log₁₀ µm).");
    const r = data.runup;
    if (r.error) failed(s, "runup");
    else {
      figure(s, r.probes.map((p, i) => ({ name: p.name || `node ${p.node}`, x: p.envelope.speed_hz.map(fromHz), y: p.envelope.magnitude_m.map((v) => (v === null ? null : v * 1e6)), mode: "lines", line: { color: palette[i % palette.length] } })),
             { title: { text: "envelope" }, xaxis: axis(speedTitle), yaxis: axis("largest |r| [µm]"), shapes: operatingShape(), height: 400 });
      figure(s, r.probes.map((p, i) => ({ name: p.name || `node ${p.node}`, x: r.time_s, y: p.dofs.v.map((v) => v * 1e6), mode: "lines", line: { color: palette[i % palette.length], width: 1 } })),
             { title: { text: "time history of v" }, xaxis: axis("time [s]"), yaxis: axis("v [µm]"), height: 380 });
      // The waterfall feran computed (the run-up's own definition, which feran.plot
      // draws too): log₁₀ of the amplitude in µm, floored at 10⁻⁶ µm. None for a run
      // of fewer than 8 samples.
      const w = r.waterfall;
      if (w) {
        const p = r.probes[w.probe];
        const z = w.amplitude_m.map((row) => row.map((a) => Math.log10(Math.max(a * 1e6, 1e-6))));
        figure(s, [{ type: "heatmap", name: "spectrum of v", x: w.frequencies_hz, y: w.speeds_hz.map(fromHz), z, colorscale: "Viridis",
                     colorbar: { title: { text: "log₁₀ µm" } }, hovertemplate: `%{x:.4g} Hz at %{y:.5g} ${unit}<br>10^%{z:.2f} µm<extra></extra>` }],
               { title: { text: `waterfall of v at ${p.name || "node " + p.node}` }, xaxis: axis("frequency [Hz]"), yaxis: axis(speedTitle), height: 460 });
      }
      r.probes.forEach((q) => numbers.push([`run-up peak at ${q.name || q.node}`, q.peak.magnitude_m * 1e6, "µm", "run-up"]));
    }
  }
};
