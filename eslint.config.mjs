// ESLint's recommended rules for feran's JavaScript: the report's script (a browser
// script, plotly.js inlined before it), its sections' modules in the analyses' folders
// and the browser tests' driver (a Node.js module). scripts/lint.sh runs it.
import js from "@eslint/js";
import globals from "globals";

export default [
  js.configs.recommended,
  {
    files: ["src/io/report/**/*.js", "src/analyses/*/report.js", "src/study/report.js"],
    languageOptions: { sourceType: "script", globals: { ...globals.browser, Plotly: "readonly" } },
  },
  {
    files: ["tests/browser/**/*.mjs"],
    // Node.js, and the functions it hands to the page run in the browser.
    languageOptions: { sourceType: "module", globals: { ...globals.node, ...globals.browser } },
  },
];
