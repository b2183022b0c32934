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
    const kinds = { spring_damper: "spring–damper", annular_seal: "annular seal", fluid_film_bearing: "journal bearing", rolling_bearing: "rolling bearing" };
    table(s, ["bearing or spring", "kind", "node", "to", `k_yy [N/m]`, `k_zz [N/m]`, "k_yz [N/m]", "k_zy [N/m]", "c_yy [N s/m]", "c_zz [N s/m]"],
      m.springs.map((b) => [b.label, kinds[b.kind] || b.kind, m.nodes[b.node_a].number, b.node_b === null ? "ground" : m.nodes[b.node_b].number,
                            fmt(b.kyy_n_per_m), fmt(b.kzz_n_per_m), fmt(b.kyz_n_per_m), fmt(b.kzy_n_per_m), fmt(b.cyy_n_s_per_m), fmt(b.czz_n_s_per_m)]));
    s.append(el("p", { class: "caption" }, `Coefficients at ${fmt(fromRpm(m.springs_at_speed_rpm), 5)} ${unit}; journal and rolling bearings by their tangent about the static equilibrium there (– where they carry nothing: an oil film at rest).`));
  }

  // ---------------------------------------------------------------- the analyses' sections
  // Each analysis's section is a module of its own (src/analyses/<name>/report.js,
  // src/study/report.js), registered in window.feranSections; feran lists the sections
  // it computed, in the report's order, in data.sections.
  const context = { data, unit, fromHz, fromRpm, freqUnit, speedTitle, verdict, unstableShapes, numbers, palette, el, fmt, sectionEl,
                    failed, figure, axis, table, operatingShape };
  for (const key of data.sections) {
    const draw = (window.feranSections || {})[key];
    if (draw) draw(context);
    else root.append(el("p", { class: "error" }, `This report's script has no section "${key}": its data is kept in the page (feran-data).`));
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
