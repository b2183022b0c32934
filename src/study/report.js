// The report's design study section (docs/report.md): registered under "study" and drawn by
// the report's script (src/io/report/report.js) from data.study, the section's data
// feran embedded.
(window.feranSections = window.feranSections || {}).study = function (report) {
  "use strict";
  const { data, el, sectionEl, figure, axis } = report;
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
};
