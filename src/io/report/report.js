// feran's interactive report: draws every section from the data the program embedded
// in <script id="feran-data"> (the documented JSON of each analysis,
// docs/output-format.md) with plotly.js, which is inlined above. Nothing is fetched.
"use strict";
(function () {
  const data = JSON.parse(document.getElementById("feran-data").textContent);
  const root = document.getElementById("report");
  const unit = data.speed_unit === "Hz" ? "Hz" : "rpm";
  const fromHz = (hz) => (hz === null ? null : unit === "Hz" ? hz : 60 * hz);
  const fromRpm = (rpm) => (rpm === null ? null : unit === "Hz" ? rpm / 60 : rpm);
  // Frequencies of the Campbell diagram in the speed's unit: Hz, or cycles per minute
  // beside rpm, so that the excitation line 1× speed is the diagonal.
  const freqUnit = unit === "Hz" ? "Hz" : "cpm";
  const speedTitle = `speed [${unit}]`;
  const config = { responsive: true, displaylogo: false, toImageButtonOptions: { format: "png", scale: 2 } };
  // A resonance peak's verdict: an unstable rotor fails there whatever its margin.
  const verdict = (k) => (k.unstable ? "FAIL: rotor unstable (no steady state)" : k.passes === null ? "not judged" : k.passes ? "pass" : "FAIL");
  // Red bands over the speeds of a steady-state result where the rotor is unstable.
  const unstableShapes = (speeds, stability) => {
    if (!stability) return [];
    const out = [];
    for (let k = 0; k < speeds.length; ++k) {
      if (stability.unstable[k] !== true) continue;
      const x0 = k > 0 ? (speeds[k - 1] + speeds[k]) / 2 : speeds[k];
      const x1 = k + 1 < speeds.length ? (speeds[k] + speeds[k + 1]) / 2 : speeds[k];
      out.push({ type: "rect", x0, x1, y0: 0, y1: 1, yref: "paper", fillcolor: "rgba(214,39,40,0.15)", line: { width: 0 } });
    }
    return out;
  };
  const plots = []; // every figure drawn: its section, its element and what it must show
  const numbers = []; // the table of numbers: [quantity, value, unit, where from]
  const palette = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22"];

  const el = (tag, attrs = {}, ...children) => {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
    for (const c of children) e.append(c);
    return e;
  };
  // Significant digits without trailing zeros: 0.0000 shows as 0, 2040.0 as 2040.
  const fmt = (x, digits = 4) => (x === null || x === undefined || !isFinite(x) ? "–" : String(Number(Number(x).toPrecision(digits))));
  const sectionEl = (id, title, intro) => {
    const s = el("section", { id });
    s.append(el("h2", {}, title));
    if (intro) s.append(el("p", { class: "intro" }, intro));
    root.append(s);
    return s;
  };
  const failed = (s, what) => s.append(el("p", { class: "error" }, `${what} failed: ${data[what]?.error ?? "no result"}`));
  let plotIndex = 0;
  // Draws one figure and records it: its traces and axis titles are what the browser
  // test checks against.
  const figure = (parent, traces, layout, caption) => {
    const id = `plot-${++plotIndex}`;
    const div = el("div", { class: "plot", id });
    parent.append(div);
    if (caption) parent.append(el("p", { class: "caption" }, caption));
    const base = { margin: { l: 70, r: 30, t: 40, b: 60 }, hovermode: "closest", legend: { orientation: "h", y: -0.22 } };
    Plotly.newPlot(div, traces, Object.assign(base, layout), config);
    plots.push({ section: parent.id || parent.closest("section").id, id });
    return div;
  };
  const axis = (title, extra = {}) => Object.assign({ title: { text: title }, zeroline: false }, extra);
  const table = (parent, head, rows) => {
    const t = el("table");
    t.append(el("thead", {}, el("tr", {}, ...head.map((h) => el("th", {}, h)))));
    const body = el("tbody");
    for (const r of rows) body.append(el("tr", {}, ...r.map((c) => el("td", {}, String(c)))));
    t.append(body);
    parent.append(t);
    return t;
  };
  const operatingShape = (yref = "paper") =>
    data.operating
      ? [{ type: "rect", xref: "x", yref, x0: fromRpm(data.operating.min_rpm), x1: fromRpm(data.operating.max_rpm), y0: 0, y1: 1,
           fillcolor: "rgba(44,160,44,0.12)", line: { width: 0 }, layer: "below" }]
      : [];

  // ---------------------------------------------------------------- header
  root.append(el("h1", {}, data.title));
  root.append(el("p", { class: "meta" },
    `feran ${data.inputs.version} · ${data.inputs.created} · model ${data.inputs.model_path}` +
    (data.operating ? ` · operating range ${fmt(fromRpm(data.operating.min_rpm), 5)}–${fmt(fromRpm(data.operating.max_rpm), 5)} ${unit}` : "")));
  if (data.complete === false)
    root.append(el("p", { class: "error" }, "Incomplete: the report was stopped on request. An analysis cut short shows its results up to there; the sections after it were not computed, and no check passes on them."));
  const nav = el("nav");
  root.append(nav);

  // ---------------------------------------------------------------- verdicts
  // One verdict per check, each with its number and reason (computed by feran from
  // the sections below: docs/report.md, "Verdicts").
  if (data.verdicts) {
    const s = sectionEl("verdicts", "Verdicts", "What to know before signing: each check, its verdict, the number that decides it and why. The sections below show where each number comes from.");
    const t = table(s, ["check", "verdict", "value", "reason"],
      data.verdicts.map((v) => [v.check, v.status, v.value === null ? "–" : `${fmt(v.value, 4)}${v.unit ? " " + v.unit : ""}`, v.reason]));
    t.classList.add("verdicts");
    t.querySelectorAll("tbody tr").forEach((tr, i) => {
      const status = data.verdicts[i].status;
      tr.children[1].classList.add(status === "pass" ? "pass" : status === "FAIL" ? "fail" : "unchecked");
    });
  }

  // ---------------------------------------------------------------- model
  {
    const m = data.model;
    const s = sectionEl("model", "Model", "The rotor drawn to scale (shaft sections, rigid bodies as solid disks of the same mass and inertias, bearings as springs to the ground), its mass properties and its bearings.");
    const traces = [];
    const shapes = [];
    for (const sh of m.shafts) {
      const ro = sh.outer_diameter_m / 2, ri = sh.inner_diameter_m / 2;
      const rob = sh.outer_diameter_b_m / 2, rib = sh.inner_diameter_b_m / 2;
      const colour = sh.rotating ? "rgba(120,120,140,0.8)" : "rgba(180,150,100,0.8)";
      // A trapezoid from end a to end b (a rectangle for a uniform element).
      const quad = (ya, yb) => `M ${sh.x_a_m} ${-ya} L ${sh.x_b_m} ${-yb} L ${sh.x_b_m} ${yb} L ${sh.x_a_m} ${ya} Z`;
      shapes.push({ type: "path", path: quad(ro, rob), fillcolor: colour, line: { width: 0.5, color: "#333" } });
      if (ri > 0 || rib > 0) shapes.push({ type: "path", path: quad(ri, rib), fillcolor: "white", line: { width: 0 } });
    }
    traces.push({ name: "shaft", x: m.shafts.flatMap((sh) => [sh.x_a_m, sh.x_b_m, null]),
                  y: m.shafts.flatMap((sh) => [sh.outer_diameter_m / 2, sh.outer_diameter_b_m / 2, null]), mode: "lines",
                  line: { color: "#555", width: 1 }, hovertemplate: "x %{x:.4f} m<br>radius %{y:.4f} m<extra>shaft</extra>" });
    for (const b of m.bodies) {
      const r = b.drawn_radius_m, w = Math.max(b.drawn_width_m, 0.004);
      shapes.push({ type: "rect", x0: b.x_m - w / 2, x1: b.x_m + w / 2, y0: -r, y1: r, fillcolor: "rgba(31,119,180,0.55)", line: { width: 0.5, color: "#1f4e79" } });
    }
    traces.push({ name: "rigid bodies", x: m.bodies.map((b) => b.x_m), y: m.bodies.map((b) => b.drawn_radius_m), mode: "markers",
                  marker: { size: 6, color: "#1f77b4" }, text: m.bodies.map((b) => `${b.label}<br>m ${fmt(b.mass_kg)} kg<br>J_A ${fmt(b.transverse_inertia_kg_m2)} kg m²<br>J_P ${fmt(b.polar_inertia_kg_m2)} kg m²`),
                  hovertemplate: "%{text}<extra></extra>" });
    const ymax = Math.max(0.01, ...m.shafts.map((x) => Math.max(x.outer_diameter_m, x.outer_diameter_b_m) / 2), ...m.bodies.map((b) => b.drawn_radius_m));
    traces.push({ name: "bearings", x: m.springs.map((b) => b.x_m), y: m.springs.map(() => -1.15 * ymax), mode: "markers",
                  marker: { symbol: "triangle-up", size: 14, color: "#d62728" },
                  text: m.springs.map((b) => `${b.label}<br>k_yy ${fmt(b.kyy_n_per_m)} N/m, k_zz ${fmt(b.kzz_n_per_m)} N/m<br>c_yy ${fmt(b.cyy_n_s_per_m)} N s/m`),
                  hovertemplate: "%{text}<extra></extra>" });
    const named = m.nodes.filter((n) => n.name);
    traces.push({ name: "nodes", x: m.nodes.map((n) => n.x_m), y: m.nodes.map(() => 0), mode: "markers", marker: { size: 4, color: "#000" },
                  text: m.nodes.map((n) => `node ${n.number}${n.name ? " (" + n.name + ")" : ""}`), hovertemplate: "%{text}<br>x %{x:.4f} m<extra></extra>" });
    const annotations = named.map((n) => ({ x: n.x_m, y: 1.3 * ymax, text: n.name, showarrow: false, textangle: -40, font: { size: 10 } }));
    figure(s, traces, { title: { text: "rotor" }, shapes, annotations, xaxis: axis("x [m]"), yaxis: axis("radius [m]", { scaleanchor: "x", scaleratio: 1 }), height: 380 });
    const rp = m.rotor;
    table(s, ["quantity", "value", "unit"], [
      ["rotor mass", fmt(rp.mass_kg, 5), "kg"], ["centre of mass x", fmt(rp.centre_of_mass_x_m, 5), "m"],
      ["transverse inertia about the centre of mass", fmt(rp.transverse_inertia_kg_m2, 5), "kg m²"],
      ["polar inertia", fmt(rp.polar_inertia_kg_m2, 5), "kg m²"], ["degrees of freedom", m.n_dofs, "–"]]);
    numbers.push(["rotor mass", rp.mass_kg, "kg", "model"], ["polar inertia", rp.polar_inertia_kg_m2, "kg m²", "model"],
                 ["transverse inertia", rp.transverse_inertia_kg_m2, "kg m²", "model"]);
    const kinds = { spring_damper: "spring–damper", fluid_film_bearing: "journal bearing", rolling_bearing: "rolling bearing" };
    table(s, ["bearing or spring", "kind", "node", "to", `k_yy [N/m]`, `k_zz [N/m]`, "k_yz [N/m]", "k_zy [N/m]", "c_yy [N s/m]", "c_zz [N s/m]"],
      m.springs.map((b) => [b.label, kinds[b.kind] || b.kind, m.nodes[b.node_a].number, b.node_b === null ? "ground" : m.nodes[b.node_b].number,
                            fmt(b.kyy_n_per_m), fmt(b.kzz_n_per_m), fmt(b.kyz_n_per_m), fmt(b.kzy_n_per_m), fmt(b.cyy_n_s_per_m), fmt(b.czz_n_s_per_m)]));
    s.append(el("p", { class: "caption" }, `Coefficients at ${fmt(fromRpm(m.springs_at_speed_rpm), 5)} ${unit}; journal and rolling bearings by their tangent about the static equilibrium there (– where they carry nothing: an oil film at rest).`));
  }

  // ---------------------------------------------------------------- Campbell
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

  // ---------------------------------------------------------------- mode shapes
  {
    const s = sectionEl("modes", "Mode shapes", "Lateral mode shapes at the chosen speeds: in 3D, animated over one period (press ▶), and in 2D (the real and imaginary parts of v and w along the rotor, largest component 1).");
    for (const entry of data.modes) {
      const r = entry.result;
      if (!r || r.error) { s.append(el("p", { class: "error" }, `modes failed: ${r ? r.error : "no result"}`)); continue; }
      const x = r.nodes.map((n) => n.x_m);
      const rotating = r.nodes.map((n) => n.rotating);
      const modes = r.modes.filter((m) => m.type === "lateral" && m.shape);
      const sub = el("div", { class: "modes-at" });
      s.append(sub);
      sub.append(el("h3", {}, `at ${fmt(fromHz(r.speed_hz), 5)} ${unit}`));
      const frames = 24;
      const traces = [], steps = [];
      const at = (m, k) => {
        const t = (2 * Math.PI * k) / frames;
        const v = m.shape.v, w = m.shape.w;
        return { y: x.map((_, i) => (rotating[i] ? v.re[i] * Math.cos(t) - v.im[i] * Math.sin(t) : null)),
                 z: x.map((_, i) => (rotating[i] ? w.re[i] * Math.cos(t) - w.im[i] * Math.sin(t) : null)) };
      };
      modes.forEach((m, j) => {
        const p = at(m, 0);
        traces.push({ type: "scatter3d", mode: "lines+markers", name: `${m.index}: ${fmt(m.frequency_hz)} Hz ${m.whirl}`, x, y: p.y, z: p.z,
                      line: { width: 5, color: palette[j % palette.length] }, marker: { size: 2 }, visible: j === 0 ? true : "legendonly" });
      });
      const animation = [];
      for (let k = 0; k < frames; ++k)
        animation.push({ name: String(k), data: modes.map((m) => { const p = at(m, k); return { x, y: p.y, z: p.z }; }) });
      for (let k = 0; k < frames; ++k) steps.push(k);
      const div = figure(sub, traces, {
        title: { text: `mode shapes in 3D at ${fmt(fromHz(r.speed_hz), 5)} ${unit}` }, height: 520,
        scene: { xaxis: { title: { text: "x [m]" } }, yaxis: { title: { text: "v" }, range: [-1.1, 1.1] }, zaxis: { title: { text: "w" }, range: [-1.1, 1.1] },
                 aspectmode: "manual", aspectratio: { x: 2.5, y: 1, z: 1 } },
        updatemenus: [{ type: "buttons", showactive: false, x: 0, y: 1.05, buttons: [
          { label: "▶", method: "animate", args: [null, { frame: { duration: 60, redraw: true }, transition: { duration: 0 }, fromcurrent: true, mode: "immediate" }] },
          { label: "❚❚", method: "animate", args: [[null], { mode: "immediate", frame: { duration: 0, redraw: false } }] }] }],
      }, "Click a legend entry to show another mode.");
      Plotly.addFrames(div, animation);
      const flat = [];
      modes.forEach((m, j) => {
        const c = palette[j % palette.length];
        flat.push({ name: `${m.index}: ${fmt(m.frequency_hz)} Hz — v`, x, y: m.shape.v.re.map((y, i) => (rotating[i] ? y : null)), mode: "lines+markers", line: { color: c } });
        flat.push({ name: `${m.index}: w`, x, y: m.shape.w.im.map((y, i) => (rotating[i] ? y : null)), mode: "lines", line: { color: c, dash: "dot" } });
      });
      figure(sub, flat, { title: { text: `mode shapes at ${fmt(fromHz(r.speed_hz), 5)} ${unit}` }, xaxis: axis("x [m]"), yaxis: axis("Re v, Im w [–]"), height: 420 });
      table(sub, ["mode", "frequency [Hz]", "damping ratio", "log. decr.", "whirl", "shape"],
            r.modes.filter((m) => m.type === "lateral").map((m) => [m.index, fmt(m.frequency_hz, 6), fmt(m.damping_ratio), fmt(m.log_decrement), m.whirl, m.shape]));
    }
  }

  // ---------------------------------------------------------------- response
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

  // ---------------------------------------------------------------- static
  if (data.static) {
    const s = sectionEl("static", "Static deflection", "Deflection under gravity and the model's static loads, and the bearing loads.");
    const st = data.static;
    if (st.error) failed(s, "static");
    else {
      if (st.stability)
        s.append(el("p", { class: st.stability.unstable ? "error" : "" },
          `At ${fmt(fromHz(st.speed_hz), 5)} ${unit}: ${st.stability.unstable ? "the rotor does not stay at this equilibrium — " : "equilibrium "}${st.stability.message}.`));
      const rot = st.displacements.filter((d) => data.model.nodes.find((n) => n.number === d.node)?.rotating);
      figure(s, [{ name: "v", x: rot.map((d) => d.x_m), y: rot.map((d) => d.v * 1e6), mode: "lines+markers" },
                 { name: "w", x: rot.map((d) => d.x_m), y: rot.map((d) => d.w * 1e6), mode: "lines+markers" }],
             { title: { text: "static deflection" }, xaxis: axis("x [m]"), yaxis: axis("deflection [µm]"), height: 360 });
      const loads = st.springs.concat(st.supports || []);
      table(s, ["bearing or spring", "F_y [N]", "F_z [N]"], loads.map((b) => [b.label, fmt(b.force.y), fmt(b.force.z)]));
      loads.forEach((b) => numbers.push([`static load of ${b.label}`, Math.hypot(b.force.y, b.force.z), "N", "static"]));
      const ops = (st.supports || []).filter((b) => b.operating && Object.keys(b.operating).length);
      if (ops.length) {
        // Every number of each bearing's operating state, its unit from its name.
        const names = [...new Set(ops.flatMap((b) => Object.keys(b.operating)))];
        const shown = { m: [1e6, "µm"], pa: [1e-6, "MPa"] };
        const head = (n) => {
          const unit = n.split("_").pop();
          return shown[unit] ? `${n.replace(/_(m|pa)$/, "")} [${shown[unit][1]}]` : n;
        };
        const value = (n, v) => { const unit = n.split("_").pop(); return fmt(v === null ? null : shown[unit] ? v * shown[unit][0] : v); };
        s.append(el("h3", {}, "Bearing operating data at the equilibrium"));
        table(s, ["bearing", ...names.map(head)], ops.map((b) => [b.label, ...names.map((n) => value(n, b.operating[n] ?? null))]));
        ops.forEach((b) => { if (b.operating.min_film_thickness_m !== undefined) numbers.push([`minimum film thickness of ${b.label}`, b.operating.min_film_thickness_m * 1e6, "µm", "static"]); });
      }
    }
  }

  // ---------------------------------------------------------------- API 684
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

  // ---------------------------------------------------------------- run-up
  if (data.runup) {
    const s = sectionEl("runup", "Run-up", "Transient run along the speed profile: the envelope of the displacement against speed, the time history and a waterfall (spectrum of v over windows of 256 samples, Hann-weighted, against speed, in log₁₀ µm).");
    const r = data.runup;
    if (r.error) failed(s, "runup");
    else {
      figure(s, r.probes.map((p, i) => ({ name: p.name || `node ${p.node}`, x: p.envelope.speed_hz.map(fromHz), y: p.envelope.magnitude_m.map((v) => (v === null ? null : v * 1e6)), mode: "lines", line: { color: palette[i % palette.length] } })),
             { title: { text: "envelope" }, xaxis: axis(speedTitle), yaxis: axis("largest |r| [µm]"), shapes: operatingShape(), height: 400 });
      figure(s, r.probes.map((p, i) => ({ name: p.name || `node ${p.node}`, x: r.time_s, y: p.dofs.v.map((v) => v * 1e6), mode: "lines", line: { color: palette[i % palette.length], width: 1 } })),
             { title: { text: "time history of v" }, xaxis: axis("time [s]"), yaxis: axis("v [µm]"), height: 380 });
      // Waterfall: spectra of v over windows of 256 samples (Hann), against the window's mean speed.
      const p = r.probes[0], n = 256, dt = r.time_s.length > 1 ? r.time_s[1] - r.time_s[0] : 1;
      const z = [], speeds = [];
      for (let start = 0; start + n <= p.dofs.v.length; start += n / 2) {
        const row = [];
        for (let k = 0; k < n / 2; ++k) {
          let re = 0, im = 0;
          for (let j = 0; j < n; ++j) {
            const w = 0.5 - 0.5 * Math.cos((2 * Math.PI * j) / (n - 1));
            const v = w * p.dofs.v[start + j];
            re += v * Math.cos((2 * Math.PI * k * j) / n);
            im -= v * Math.sin((2 * Math.PI * k * j) / n);
          }
          row.push(Math.log10(Math.max((4 * Math.hypot(re, im)) / n * 1e6, 1e-6)));
        }
        z.push(row);
        speeds.push(fromHz(r.speed_hz[start + n / 2]));
      }
      const freqs = Array.from({ length: n / 2 }, (_, k) => k / (n * dt));
      figure(s, [{ type: "heatmap", name: "spectrum of v", x: freqs, y: speeds, z, colorscale: "Viridis", colorbar: { title: { text: "log₁₀ µm" } },
                   hovertemplate: `%{x:.4g} Hz at %{y:.5g} ${unit}<br>10^%{z:.2f} µm<extra></extra>` }],
             { title: { text: `waterfall of v at ${p.name || "node " + p.node}` }, xaxis: axis("frequency [Hz]"), yaxis: axis(speedTitle), height: 460 });
      r.probes.forEach((q) => numbers.push([`run-up peak at ${q.name || q.node}`, q.peak.magnitude_m * 1e6, "µm", "run-up"]));
    }
  }

  // ---------------------------------------------------------------- study
  if (data.study) {
    const s = sectionEl("study", "Design study", "The designs of a study's output: the Pareto front (or the objective against the designs) and the parallel coordinates of every feasible design.");
    const st = data.study, evals = st.evaluations.filter((e) => e.evaluated && e.quantities);
    const feasible = evals.filter((e) => e.feasible);
    const vars = st.study.variables.map((v) => v.name), qs = st.study.quantities.map((q) => q.name);
    const objectives = (st.study.objectives || []).map((o) => o.quantity || o.name || o);
    if (objectives.length >= 2) {
      const [a, b] = objectives;
      const front = st.summary && st.summary.pareto ? st.summary.pareto : [];
      figure(s, [{ name: "feasible designs", x: feasible.map((e) => e.quantities[a]), y: feasible.map((e) => e.quantities[b]), mode: "markers", marker: { color: "#bbb", size: 5 } },
                 { name: "Pareto front", x: front.map((e) => e.quantities[a]), y: front.map((e) => e.quantities[b]), mode: "markers", marker: { color: "#d62728", size: 8 } }],
             { title: { text: "Pareto front" }, xaxis: axis(a), yaxis: axis(b), height: 420 });
    } else if (objectives.length === 1) {
      const a = objectives[0];
      figure(s, [{ name: a, x: feasible.map((e) => e.index), y: feasible.map((e) => e.quantities[a]), mode: "markers" }],
             { title: { text: `objective ${a} of each feasible design` }, xaxis: axis("design"), yaxis: axis(a), height: 380 });
    }
    const dims = vars.map((v) => ({ label: v, values: feasible.map((e) => e.variables[v]) }))
      .concat(qs.filter((q) => feasible.every((e) => isFinite(e.quantities[q]))).map((q) => ({ label: q, values: feasible.map((e) => e.quantities[q]) })));
    if (dims.length && feasible.length)
      figure(s, [{ type: "parcoords", name: "designs", dimensions: dims, line: { color: dims[dims.length - 1].values, colorscale: "Viridis", showscale: true } }],
             { title: { text: "parallel coordinates" }, height: 460, margin: { l: 80, r: 80, t: 80, b: 40 } });
    s.append(el("p", {}, `${st.evaluations.length} designs, ${evals.length} evaluated, ${feasible.length} feasible.`));
  }

  // ---------------------------------------------------------------- numbers and inputs
  {
    const s = sectionEl("numbers", "Numbers and inputs", "Every number of the report with its unit, and what produced it.");
    table(s, ["quantity", "value", "unit", "from"], numbers.map(([q, v, u, f]) => [q, fmt(v, 6), u, f]));
    table(s, ["input", "value"], [["model file", data.inputs.model_path], ["command", data.inputs.command || "–"], ["feran version", data.inputs.version], ["created", data.inputs.created]]);
    const details = el("details");
    details.append(el("summary", {}, "the model as read (TOML)"), el("pre", {}, data.inputs.model_text));
    s.append(details);
  }

  for (const sec of root.querySelectorAll("section")) nav.append(el("a", { href: `#${sec.id}` }, sec.querySelector("h2").textContent));
  // What the browser test reads.
  window.feranReport = { plots, numbers: numbers.length, ready: true };
})();
