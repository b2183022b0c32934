// The report's static deflection section (docs/report.md): registered under "static" and drawn by
// the report's script (src/io/report/report.js) from data.static, the section's data
// feran embedded.
(window.feranSections = window.feranSections || {}).static = function (report) {
  "use strict";
  const { data, unit, fromHz, numbers, el, fmt, sectionEl, failed, figure, axis, table } = report;
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
};
