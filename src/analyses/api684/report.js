// The report's API 617 / API 684 section (docs/report.md): registered under "api684" and drawn by
// the report's script (src/io/report/report.js) from data.api684, the section's data
// feran embedded.
(window.feranSections = window.feranSections || {}).api684 = function (report) {
  "use strict";
  const { data, unit, fromRpm, speedTitle, verdict, numbers, palette, el, fmt, sectionEl, failed, figure, axis, table, operatingShape } = report;
  if (data.api684) {
    const s = sectionEl("api684", "API 617 / API 684", "Unbalance responses to the analytical unbalance 4W/N placed for each mode, each resonance judged by its amplification factor (half-power method) and the separation margin API 617 requires; the undamped critical speed map; the level I stability analysis.");
    const a = data.api684;
    if (a.error) failed(s, "api684");
    else {
      s.append(el("p", { class: a.operating_stability.passes ? "pass" : "fail" },
                  `Stability in the operating range: ${a.operating_stability.passes ? "passes" : "FAILS"} (${a.operating_stability.reason}).`));
      for (const c of a.cases) {
        const sub = el("div", { class: "case" });
        s.append(sub);
        sub.append(el("h3", {}, `${c.name}: ${c.passes ? "passes" : "FAILS"}`));
        sub.append(el("p", {}, c.unbalances.map((u) => `${fmt(u.amount_g_mm)} g mm at ${u.name || "node " + u.node}, ${fmt(u.phase_deg, 3)}° (W = ${fmt(u.journal_mass_kg)} kg, ${u.basis})`).join("; ")));
        const sp = c.speeds_rpm.map(fromRpm);
        const traces = c.probes.map((p, i) => ({ name: p.name || `node ${p.node}`, x: sp, y: p.amplitude_m.map((v) => v * 1e6), mode: "lines", line: { color: palette[i % palette.length] } }));
        const peaks = c.probes.flatMap((p) => p.peaks.filter((k) => k.amplification_factor !== null).map((k) => ({ p, k })));
        traces.push({ name: "peaks (AF, SM)", x: peaks.map((q) => fromRpm(q.k.speed_rpm)), y: peaks.map((q) => q.k.amplitude_m * 1e6), mode: "markers",
                      marker: { symbol: peaks.map((q) => (q.k.passes ? "circle" : "x")), size: 10, color: peaks.map((q) => (q.k.passes ? "#2ca02c" : "#d62728")) },
                      text: peaks.map((q) => `AF ${fmt(q.k.amplification_factor, 3)}<br>SM required ${fmt(100 * q.k.required_margin, 3)} %, actual ${fmt(100 * q.k.actual_margin, 3)} %`),
                      hovertemplate: `%{x:.5g} ${unit}<br>%{text}<extra></extra>` });
        const shapes = operatingShape();
        for (const q of peaks)
          if (q.k.required_margin > 0) {
            const n = fromRpm(q.k.speed_rpm), below = q.k.speed_rpm < a.operating.min_rpm;
            const edge = below ? n * (1 + q.k.required_margin) : n * (1 - q.k.required_margin);
            shapes.push({ type: "rect", x0: Math.min(n, edge), x1: Math.max(n, edge), y0: 0, y1: 1, yref: "paper", fillcolor: "rgba(214,39,40,0.08)", line: { width: 0 } });
          }
        figure(sub, traces, { title: { text: `${c.name}: unbalance response` }, xaxis: axis(speedTitle), yaxis: axis("amplitude [µm]"), shapes, height: 400 },
               "Green band: operating range; red bands: the separation margin each peak requires.");
        table(sub, ["probe", `peak [${unit}]`, "amplitude [µm]", "AF", "SM required", "SM actual", "verdict"],
              c.probes.flatMap((p) => p.peaks.map((k) => [p.name || p.node, fmt(fromRpm(k.speed_rpm), 6), fmt(k.amplitude_m * 1e6), fmt(k.amplification_factor, 3),
                k.required_margin === null ? "–" : `${fmt(100 * k.required_margin, 3)} %`, `${fmt(100 * k.actual_margin, 3)} %`,
                verdict(k)])));
        for (const q of peaks) numbers.push([`${c.name}: AF at ${q.p.name || q.p.node}, ${fmt(fromRpm(q.k.speed_rpm), 5)} ${unit}`, q.k.amplification_factor, "–", "API 684"]);
      }
      if (a.map) {
        const m = a.map;
        const traces = m.criticals_rpm.map((line, n) => ({ name: `critical ${n + 1}`, x: m.stiffness_n_per_m, y: line.map(fromRpm), mode: "lines", line: { color: palette[n % palette.length] } }));
        m.curves.forEach((c, i) => traces.push({ name: `${c.bearing} k_${c.direction}${c.direction}`, x: c.stiffness_n_per_m, y: c.speeds_rpm.map(fromRpm), mode: "lines",
                                                  line: { dash: "dash", color: "#555", width: 1 + (i % 2) } }));
        traces.push({ name: "intersections", x: m.intersections.map((x) => x.stiffness_n_per_m), y: m.intersections.map((x) => fromRpm(x.speed_rpm)), mode: "markers",
                      marker: { size: 10, symbol: "circle-open", color: "#000" }, hovertemplate: `%{x:.4g} N/m<br>%{y:.5g} ${unit}<extra>intersection</extra>` });
        figure(s, traces, { title: { text: "undamped critical speed map" }, xaxis: axis("bearing stiffness [N/m]", { type: "log" }),
                            yaxis: axis(`critical speed [${unit}]`, { type: "log" }), shapes: data.operating ? [{ type: "rect", xref: "paper", x0: 0, x1: 1, y0: fromRpm(a.operating.min_rpm), y1: fromRpm(a.operating.max_rpm), fillcolor: "rgba(44,160,44,0.12)", line: { width: 0 }, layer: "below" }] : [], height: 520 });
      }
      if (a.stability) {
        const st = a.stability;
        const traces = [{ name: "first forward mode", x: st.q_n_per_m.map((q) => q / 1e6), y: st.log_decrement, mode: "lines+markers" }];
        if (st.q_zero_n_per_m !== null) traces.push({ name: "Q₀", x: [st.q_zero_n_per_m / 1e6], y: [0], mode: "markers", marker: { size: 12, symbol: "x", color: "#d62728" } });
        if (st.anticipated_n_per_m !== null) traces.push({ name: "q_A", x: [st.anticipated_n_per_m / 1e6], y: [st.log_decrement_at_anticipated], mode: "markers", marker: { size: 12, symbol: "diamond", color: "#ff7f0e" } });
        figure(s, traces, { title: { text: `level I stability at ${fmt(fromRpm(st.speed_rpm), 5)} ${unit}, Q at ${st.name || "node " + st.node}` },
                            xaxis: axis("cross-coupled stiffness Q [MN/m]"), yaxis: axis("log. decrement [–]"), height: 400 });
        s.append(el("p", {}, `Q₀ = ${fmt(st.q_zero_n_per_m)} N/m` + (st.anticipated_n_per_m !== null ? `; q_A = ${fmt(st.anticipated_n_per_m)} N/m, Q₀/q_A = ${fmt(st.q_zero_n_per_m / st.anticipated_n_per_m, 3)}, δ(q_A) = ${fmt(st.log_decrement_at_anticipated)}: ${st.screening_passes ? "passes level I" : "level II required"}.` : ".")));
        numbers.push(["Q₀ (level I)", st.q_zero_n_per_m, "N/m", "API 617"]);
      }
    }
  }
};
