// The report's mode shapes section (docs/report.md): registered under "modes" and drawn by
// the report's script (src/io/report/report.js) from data.modes, the section's data
// feran embedded.
(window.feranSections = window.feranSections || {}).modes = function (report) {
  "use strict";
  const { data, unit, fromHz, palette, el, fmt, sectionEl, figure, axis, table } = report;
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
};
