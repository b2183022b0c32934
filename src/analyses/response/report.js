// The report's unbalance response section (docs/report.md): registered under "response" and drawn by
// the report's script (src/io/report/report.js) from data.response, the section's data
// feran embedded.
(window.feranSections = window.feranSections || {}).response = function (report) {
  "use strict";
  const { data, unit, fromHz, fromRpm, speedTitle, verdict, unstableShapes, numbers, palette, fmt, sectionEl, failed, figure, axis, table, operatingShape } = report;
  const campbell = data.campbell;
  if (data.response) {
    const s = sectionEl("response", "Unbalance response", "Steady-state response to the model's unbalances and forces: amplitude (orbit semi-major axis) and phase at each probe, the polar plot, the deflected shape at one speed, bearing forces and shaft stress against speed.");
    const r = data.response;
    if (r.error) failed(s, "response");
    else {
      const sp = r.speeds_hz.map(fromHz);
      const critShapes = operatingShape().concat(unstableShapes(sp, r.stability), campbell.critical_speeds.filter((c) => c.order === 1 && c.whirl === "forward").map((c) => ({
        type: "line", x0: fromHz(c.speed_hz), x1: fromHz(c.speed_hz), y0: 0, y1: 1, yref: "paper", line: { dash: "dot", color: "#999" } })));
      const bode = r.probes.map((p, i) => ({ name: p.name || `node ${p.node}`, x: sp, y: p.amplitude_m.map((a) => a * 1e6), mode: "lines", line: { color: palette[i % palette.length] },
                                             hovertemplate: `%{x:.5g} ${unit}<br>%{y:.4g} µm<extra>${p.name || p.node}</extra>` }));
      const judged = (r.peaks || []).filter((k) => k.amplification_factor !== null);
      if (r.peaks)
        bode.push({ name: "peaks (AF, SM)", x: judged.map((k) => fromRpm(k.speed_rpm)), y: judged.map((k) => k.amplitude_m * 1e6), mode: "markers",
                    marker: { size: 10, symbol: judged.map((k) => (k.passes ? "circle" : "x")), color: judged.map((k) => (k.passes ? "#2ca02c" : "#d62728")) },
                    text: judged.map((k) => `AF ${fmt(k.amplification_factor, 3)}<br>SM required ${fmt(100 * k.required_margin, 3)} %, actual ${fmt(100 * k.actual_margin, 3)} %`),
                    hovertemplate: `%{x:.5g} ${unit}<br>%{text}<extra></extra>` });
      figure(s, bode, { title: { text: "amplitude (Bode)" }, xaxis: axis(speedTitle), yaxis: axis("amplitude [µm]"), shapes: critShapes, height: 420 },
             "Dotted: forward critical speeds of the Campbell diagram; green band: the operating range" +
             (r.stability && r.stability.unstable_points > 0 ? `; red bands: the rotor is UNSTABLE there (from ${fmt(fromHz(r.stability.first_unstable_speed_hz), 5)} ${unit}): no steady state, any disturbance grows` : "") +
             (r.peaks ? "; markers: resonance peaks with their amplification factor and separation margins (● passes API 617, × fails; hover)." : "."));
      if (r.peaks)
        table(s, ["probe", `peak [${unit}]`, "amplitude [µm]", "AF", "SM required", "SM actual", "verdict"],
              r.peaks.map((k) => [r.probes[k.probe].name || r.probes[k.probe].node, fmt(fromRpm(k.speed_rpm), 6), fmt(k.amplitude_m * 1e6),
                                  fmt(k.amplification_factor, 3), k.required_margin === null ? "–" : `${fmt(100 * k.required_margin, 3)} %`,
                                  `${fmt(100 * k.actual_margin, 3)} %`, verdict(k)]));
      figure(s, r.probes.map((p, i) => ({ name: p.name || `node ${p.node}`, x: sp, y: p.phase_deg, mode: "lines", line: { color: palette[i % palette.length] } })),
             { title: { text: "phase of v (Bode)" }, xaxis: axis(speedTitle), yaxis: axis("phase [deg]"), shapes: critShapes, height: 360 });
      figure(s, r.probes.map((p, i) => ({ type: "scatterpolar", name: p.name || `node ${p.node}`, r: p.dofs.v.amplitude.map((a) => a * 1e6), theta: p.dofs.v.phase_deg,
                                          mode: "lines", line: { color: palette[i % palette.length] }, text: sp.map((x) => `${fmt(x, 5)} ${unit}`),
                                          hovertemplate: "%{text}<br>%{r:.4g} µm at %{theta:.1f}°<extra></extra>" })),
             { title: { text: "polar plot of v [µm]" }, polar: { radialaxis: { title: { text: "amplitude [µm]" } } }, height: 460 });
      const shape = r.deflected_shape;
      if (shape && shape.probes) {
        const nodes = shape.probes.filter((p) => data.model.nodes.find((n) => n.number === p.node)?.rotating);
        figure(s, [{ name: "orbit semi-major axis", x: nodes.map((p) => p.x_m), y: nodes.map((p) => p.amplitude_m[0] * 1e6), mode: "lines+markers" },
                   { name: "v (real part)", x: nodes.map((p) => p.x_m), y: nodes.map((p) => p.dofs.v.amplitude[0] * Math.cos((p.dofs.v.phase_deg[0] * Math.PI) / 180) * 1e6), mode: "lines", line: { dash: "dot" } }],
               { title: { text: `deflected shape at ${fmt(fromHz(shape.speeds_hz[0]), 5)} ${unit}` }, xaxis: axis("x [m]"), yaxis: axis("deflection [µm]"), height: 380 });
      }
      if (r.springs.length)
        figure(s, r.springs.map((b, i) => ({ name: b.label, x: sp, y: b.peak_lateral_force_n, mode: "lines", line: { color: palette[i % palette.length] } })),
               { title: { text: "bearing and spring forces" }, xaxis: axis(speedTitle), yaxis: axis("peak lateral force [N]"), shapes: operatingShape(), height: 380 });
      if (r.station_peaks)
        figure(s, [{ name: "largest von Mises stress", x: sp, y: r.station_peaks.von_mises.value_pa.map((v) => v / 1e6), mode: "lines",
                     customdata: r.station_peaks.von_mises.x_m, hovertemplate: `%{x:.5g} ${unit}<br>%{y:.4g} MPa at x = %{customdata:.3f} m<extra></extra>` }],
               { title: { text: "shaft stress" }, xaxis: axis(speedTitle), yaxis: axis("von Mises stress [MPa]"), shapes: operatingShape(), height: 360 });
      r.summary.probes.forEach((p) => numbers.push([`peak response at ${p.name || p.node}`, p.peak_amplitude_m * 1e6, "µm", "response"]));
      if (r.summary.largest_stress) numbers.push(["largest shaft stress", r.summary.largest_stress.von_mises_pa / 1e6, "MPa", "response"]);
    }
  }
};
