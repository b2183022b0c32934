// The report's Campbell diagram, damping and bearings-over-speed section (docs/report.md): registered under "campbell" and drawn by
// the report's script (src/io/report/report.js) from data.campbell, the section's data
// feran embedded.
(window.feranSections = window.feranSections || {}).campbell = function (report) {
  "use strict";
  const { data, unit, fromHz, freqUnit, speedTitle, numbers, palette, el, fmt, sectionEl, figure, axis, table, operatingShape } = report;
  const campbell = data.campbell;
  {
    const s = sectionEl("campbell", "Campbell diagram", "Natural frequencies against speed. Colour: logarithmic decrement (red below zero: unstable; blue: well damped); marker: whirl (▲ forward, ▼ backward, ● mixed or planar). Dashed: excitation orders; ◆ critical speeds; green band: operating range; red line: stability threshold.");
    const sp = campbell.speeds_hz.map(fromHz);
    const lateral = campbell.modes.filter((m) => m.type !== "axial" && m.type !== "torsional");
    const allDelta = lateral.flatMap((m) => m.log_decrement.filter((d) => d !== null));
    // Diverging and symmetric about zero damping: red below zero (unstable), blue well
    // damped — the scale feran.plot.campbell uses too.
    const dampingScale = [[0, "#b2182b"], [0.25, "#ef8a62"], [0.5, "#f7f7f7"], [0.75, "#67a9cf"], [1, "#2166ac"]];
    const dmax = Math.max(0.05, ...allDelta.map(Math.abs));
    const traces = lateral.map((m, i) => ({
      name: m.label, x: sp, y: m.frequency_hz.map(fromHz), mode: "lines+markers", line: { color: "rgba(90,90,90,0.5)", width: 1 },
      marker: { size: 6, color: m.log_decrement, cmin: -dmax, cmax: dmax, colorscale: dampingScale,
                symbol: m.whirl_at.map((w) => (w === "forward" ? "triangle-up" : w === "backward" ? "triangle-down" : "circle")),
                colorbar: i === 0 ? { title: { text: "log. decr." } } : undefined, showscale: i === 0 },
      customdata: m.log_decrement, hovertemplate: `${m.label}<br>%{x:.4g} ${unit}<br>%{y:.4g} ${freqUnit}<br>δ %{customdata:.4f}<extra></extra>` }));
    const top = Math.max(...lateral.flatMap((m) => m.frequency_hz.filter((f) => f !== null).map(fromHz)), 1);
    for (const k of campbell.orders)
      traces.push({ name: `${k}× speed`, x: [sp[0], sp[sp.length - 1]], y: [k * sp[0], k * sp[sp.length - 1]],
                    mode: "lines", line: { dash: "dash", color: "#444" }, hoverinfo: "skip" });
    const crit = campbell.critical_speeds;
    traces.push({ name: "critical speeds", x: crit.map((c) => fromHz(c.speed_hz)), y: crit.map((c) => fromHz(c.frequency_hz)), mode: "markers",
                  marker: { symbol: "diamond", size: 11, color: "#000", line: { color: "#fff", width: 1 } },
                  text: crit.map((c) => `${c.mode}, order ${c.order}, ${c.whirl}`), hovertemplate: `%{text}<br>%{x:.5g} ${unit}<extra>critical speed</extra>` });
    const shapes = operatingShape();
    if (campbell.stability_threshold)
      shapes.push({ type: "line", x0: fromHz(campbell.stability_threshold.speed_hz), x1: fromHz(campbell.stability_threshold.speed_hz), y0: 0, y1: 1, yref: "paper", line: { color: "#d62728", width: 2 } });
    figure(s, traces, { title: { text: "Campbell diagram" }, xaxis: axis(speedTitle), yaxis: axis(`frequency [${freqUnit}]`, { range: [0, 1.05 * top] }), shapes, height: 520 });
    table(s, ["critical speed", `speed [${unit}]`, "order", "whirl"], crit.map((c) => [c.mode, fmt(fromHz(c.speed_hz), 6), c.order, c.whirl]));
    crit.forEach((c) => numbers.push([`critical speed (${c.mode}, ${c.order}×)`, fromHz(c.speed_hz), unit, "Campbell"]));
    numbers.push(["stability threshold", campbell.stability_threshold ? fromHz(campbell.stability_threshold.speed_hz) : null, unit, "Campbell"]);
    s.append(el("p", {}, campbell.stability_threshold ? `Stability threshold: ${fmt(fromHz(campbell.stability_threshold.speed_hz), 5)} ${unit} (${campbell.stability_threshold.mode}).` :
      `No mode becomes unstable up to ${fmt(sp[sp.length - 1], 5)} ${unit}.`));

    const d = sectionEl("damping", "Damping against speed", "Logarithmic decrement of each lateral mode: below zero the mode grows.");
    figure(d, lateral.map((m, i) => ({ name: m.label, x: sp, y: m.log_decrement, mode: "lines", line: { color: palette[i % palette.length] },
                                       hovertemplate: `${m.label}<br>%{x:.4g} ${unit}<br>δ %{y:.4f}<extra></extra>` })),
           { title: { text: "logarithmic decrement" }, xaxis: axis(speedTitle), yaxis: axis("log. decrement [–]"), shapes: operatingShape(), height: 420 });

    // Each bearing's state at the equilibrium at each speed of the diagram, about which
    // its coefficients are linearised: one figure per quantity some bearing has.
    const bearings = (campbell.supports || []).filter((b) => b.operating && Object.keys(b.operating).length);
    if (bearings.length) {
      const b = sectionEl("bearings", "Bearings over speed", "Each bearing's operating state at the static equilibrium at each speed of the Campbell diagram, about which its stiffness and damping are linearised. Dotted: Trumpler's design limits (minimum film thickness 5.08 µm + 4·10⁻⁵·D; unit load 2.07 MPa).");
      const plotted = [["eccentricity_ratio", "eccentricity ratio [–]", 1, null],
                       ["min_film_thickness_m", "minimum film thickness [µm]", 1e6, "min_film_limit_m"],
                       ["sommerfeld_number", "Sommerfeld number [–]", 1, null],
                       ["power_loss_w", "friction power loss [W]", 1, null],
                       ["max_element_load_n", "most loaded element [N]", 1, null],
                       ["max_contact_stress_pa", "Hertz contact stress [MPa]", 1e-6, "contact_stress_limit_pa"]];
      for (const [name, title, scale, limit] of plotted) {
        const having = bearings.filter((x) => x.operating[name]);
        if (!having.length) continue;
        const traces = having.map((x, i) => ({ name: x.label, x: sp, y: x.operating[name].map((v) => (v === null ? null : v * scale)), mode: "lines",
                                               line: { color: palette[i % palette.length] }, hovertemplate: `${x.label}<br>%{x:.4g} ${unit}<br>%{y:.4g}<extra></extra>` }));
        having.forEach((x, i) => {
          const l = limit && x.operating[limit] ? x.operating[limit].find((v) => v !== null) : null;
          if (l) traces.push({ name: `${x.label} limit`, x: [sp[0], sp[sp.length - 1]], y: [l * scale, l * scale], mode: "lines",
                               line: { dash: "dot", color: palette[i % palette.length] }, hoverinfo: "skip" });
        });
        figure(b, traces, { title: { text: title }, xaxis: axis(speedTitle), yaxis: axis(title), shapes: operatingShape(), height: 340 });
      }
      if (data.operating) {
        // The thinnest film within the operating range, for the numbers table.
        const lo = data.operating.min_rpm / 60, hi = data.operating.max_rpm / 60;
        bearings.forEach((x) => {
          const h = (x.operating.min_film_thickness_m || []).filter((v, k) => v !== null && campbell.speeds_hz[k] >= lo && campbell.speeds_hz[k] <= hi);
          if (h.length) numbers.push([`thinnest film of ${x.label} in the operating range`, Math.min(...h) * 1e6, "µm", "Campbell"]);
        });
      }
    }
  }
};
