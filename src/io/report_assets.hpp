#pragma once
// The report's scripts and style sheet, built into the library (report_assets.cpp).

#include <string_view>

namespace feran::detail {

/// False when the library was built without plotly.js (the front-end packages were
/// not installed): the texts below are then empty.
bool report_assets_built();
std::string_view plotly_js();
std::string_view report_js();
std::string_view report_css();

}  // namespace feran::detail
