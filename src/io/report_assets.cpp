// The report's scripts and style, built into the library: plotly.js from the npm
// package plotly.js-dist-min (installed by scripts/setup.sh) and the report's own
// script and style sheet (src/io/report/). The assembler's .incbin copies each file's
// bytes into read-only data at build time; nothing is read or fetched at run time.
#include "report_assets.hpp"

#ifdef FERAN_PLOTLY_JS

#define FERAN_EMBED(name, path)         \
  asm(".section .rodata\n"              \
      ".globl " #name                   \
      "_begin\n"                        \
      ".hidden " #name                  \
      "_begin\n"                        \
      ".globl " #name                   \
      "_end\n"                          \
      ".hidden " #name                  \
      "_end\n"                          \
      ".balign 16\n" #name              \
      "_begin:\n"                       \
      ".incbin \"" path "\"\n" #name    \
      "_end:\n"                         \
      ".byte 0\n"                       \
      ".previous\n");                   \
  extern "C" const char name##_begin[]; \
  extern "C" const char name##_end[];

FERAN_EMBED(feran_plotly_js, FERAN_PLOTLY_JS)
FERAN_EMBED(feran_report_js, FERAN_REPORT_JS)
FERAN_EMBED(feran_report_css, FERAN_REPORT_CSS)

namespace feran::detail {

bool report_assets_built() { return true; }
std::string_view plotly_js() {
  return {feran_plotly_js_begin, static_cast<std::size_t>(feran_plotly_js_end - feran_plotly_js_begin)};
}
std::string_view report_js() {
  return {feran_report_js_begin, static_cast<std::size_t>(feran_report_js_end - feran_report_js_begin)};
}
std::string_view report_css() {
  return {feran_report_css_begin, static_cast<std::size_t>(feran_report_css_end - feran_report_css_begin)};
}

}  // namespace feran::detail

#else

namespace feran::detail {

bool report_assets_built() { return false; }
std::string_view plotly_js() { return {}; }
std::string_view report_js() { return {}; }
std::string_view report_css() { return {}; }

}  // namespace feran::detail

#endif
