// The report's data: the rotor's mass properties against the closed forms of a
// uniform shaft, the sections present for what the model gives, text that would end
// the data's <script> element kept inside it, and the configuration file's located
// errors. (The page itself is checked in a browser: tests/browser/.)
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <feran/core/error.hpp>
#include <feran/io/html_report.hpp>
#include <feran/io/model_reader.hpp>
#include <feran/io/report_config.hpp>

namespace feran::test_html_report {
namespace {


// A uniform steel shaft, 0.8 m × Ø 40 mm, on two bearings.
std::string shaft_model(const std::string& title, const std::string& extra = "") {
  return "title = \"" + title + "\"\n" + R"(
[[materials]]
name = "steel"
E = 2.11e11
G = 8.12e10
rho = 7810
[[shafts]]
material = "steel"
start_node = "left"
sections = [{ length = 0.8, outer_diameter = 0.04, elements = 8, end_node = "right" }]
[[springs]]
name = "bearing 1"
node = "left"
ky = 1e7
kz = 1e7
cy = 500
cz = 500
kx = 1e7
krx = 1e4
[[springs]]
name = "bearing 2"
node = "right"
ky = 1e7
kz = 1e7
cy = 500
cz = 500
[[unbalances]]
node = 5
mass = 0.001
radius = 0.02
[campbell]
stop = "6000 rpm"
points = 11
[response]
stop = "6000 rpm"
points = 31
)" + extra;
}

nlohmann::json report_data(const std::string& html) {
  const std::string open = "<script id=\"feran-data\" type=\"application/json\">\n";
  const std::size_t a = html.find(open);
  EXPECT_NE(a, std::string::npos);
  const std::size_t b = html.find("\n</script>", a);
  return nlohmann::json::parse(html.substr(a + open.size(), b - a - open.size()));
}

TEST(HtmlReport, HoldsTheMassPropertiesOfAUniformShaft) {
  if (!report_available()) GTEST_SKIP() << "built without plotly.js";
  const ModelFile file = read_model_string(shaft_model("uniform shaft"), "shaft.toml");
  ReportOptions options;
  options.runup = false;
  options.n_threads = 1;
  const nlohmann::json d = report_data(html_report(file, options));
  // m = ρπr²L, J_P = m r²/2, J_T = m(L²/12 + r²/4) about the middle: the consistent
  // mass matrix integrates rigid motions exactly (1e-12; round-off of 8 elements).
  const Real r = 0.02, L = 0.8, m = 7810 * pi * r * r * L;
  const auto& rotor = d["model"]["rotor"];
  EXPECT_NEAR(rotor["mass_kg"].get<Real>() / m - 1, 0, 1e-12);
  EXPECT_NEAR(rotor["centre_of_mass_x_m"].get<Real>(), L / 2, 1e-12);
  EXPECT_NEAR(rotor["polar_inertia_kg_m2"].get<Real>() / (m * r * r / 2) - 1, 0, 1e-12);
  EXPECT_NEAR(rotor["transverse_inertia_kg_m2"].get<Real>() / (m * (L * L / 12 + r * r / 4)) - 1, 0, 1e-12);
  EXPECT_EQ(d["model"]["shafts"].size(), 8u);
  EXPECT_EQ(d["model"]["springs"].size(), 2u);
  // Sections: Campbell, modes at 0 and the Campbell diagram's last speed, the
  // response (the model has an unbalance), static; no API 684 without a range.
  EXPECT_EQ(d["campbell"]["speeds_hz"].size(), 11u);
  ASSERT_EQ(d["modes"].size(), 2u);
  EXPECT_NEAR(d["modes"][1]["result"]["speed_hz"].get<Real>(), 100.0, 1e-9);
  EXPECT_TRUE(d.contains("response") && d["response"].contains("deflected_shape"));
  EXPECT_TRUE(d.contains("static"));
  EXPECT_FALSE(d.contains("api684"));
  EXPECT_FALSE(d.contains("runup"));
}

TEST(HtmlReport, KeepsTextThatWouldEndItsScriptInsideTheData) {
  if (!report_available()) GTEST_SKIP() << "built without plotly.js";
  const std::string title = "a </script><script>alert(1)</script> rotor";
  const ModelFile file = read_model_string(shaft_model(title), "shaft.toml");
  ReportOptions options;
  options.runup = false;
  options.static_analysis = false;
  options.n_threads = 1;
  const std::string html = html_report(file, options);
  // Only "</" ends a script element: it is written "<\/" inside the data, "&lt;/" in the title.
  EXPECT_EQ(html.find("</script><script>alert"), std::string::npos);
  EXPECT_EQ(report_data(html)["title"], title);
}

TEST(HtmlReport, RunsTheApi684SectionWhenTheModelGivesAnOperatingRange) {
  if (!report_available()) GTEST_SKIP() << "built without plotly.js";
  const ModelFile file = read_model_string(
      shaft_model("shaft", "[api684]\nmin_speed = \"2000 rpm\"\nmax_speed = \"3000 rpm\"\npoints = 41\nmap_points = 5\n"),
      "shaft.toml");
  ReportOptions options;
  options.runup = false;
  options.n_threads = 1;
  const nlohmann::json d = report_data(html_report(file, options));
  ASSERT_TRUE(d.contains("api684"));
  EXPECT_FALSE(d["api684"].contains("error"));
  EXPECT_EQ(d["api684"]["map"]["stiffness_n_per_m"].size(), 5u);
  EXPECT_NEAR(d["operating"]["max_rpm"].get<Real>(), 3000, 1e-9);
  options.speed_unit = "rad/s";
  EXPECT_THROW(html_report(file, options), Error);
}

TEST(ReportConfig, ReadsItsKeysAndLocatesMistakes) {
  const ModelFile file = read_model_string(shaft_model("shaft"), "shaft.toml");
  ReportOptions options;
  read_report_config("title = \"T\"\nspeed_unit = \"Hz\"\n[campbell]\nstop = \"50 Hz\"\n[modes]\nspeeds = [0, \"10 Hz\"]\n"
                     "[response]\nprobes = [\"left\", 5]\n[runup]\nenabled = false\n",
                     "report.toml", file.model, options);
  EXPECT_EQ(options.title, "T");
  EXPECT_EQ(options.speed_unit, "Hz");
  EXPECT_NEAR(*options.campbell.stop, 2 * pi * 50, 1e-9);
  ASSERT_EQ(options.mode_speeds.size(), 2u);
  EXPECT_NEAR(options.mode_speeds[1], 2 * pi * 10, 1e-9);
  EXPECT_EQ(options.response.probes, (std::vector<Index>{0, 4}));
  EXPECT_FALSE(options.runup);
  const auto message = [&](const std::string& text) {
    try {
      ReportOptions o;
      read_report_config(text, "report.toml", file.model, o);
    } catch (const ModelError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("[campbell]\nstpo = \"50 Hz\"\n").find("report.toml:2:1"), std::string::npos);
  EXPECT_NE(message("[campbell]\nstpo = \"50 Hz\"\n").find("did you mean 'stop'"), std::string::npos);
  EXPECT_NE(message("speed_unit = \"rad/s\"\n").find("report.toml:1:14"), std::string::npos);
  EXPECT_NE(message("[response]\nprobes = [\"middle\"]\n").find("no such node"), std::string::npos);
  EXPECT_NE(message("[modes]\nspeeds = [\"-5 Hz\"]\n").find("report.toml:2:"), std::string::npos);
  EXPECT_NE(message("[study]\ndirectory = \"nowhere\"\n").find("does not exist"), std::string::npos);
  EXPECT_NE(message("title = \n").find("report.toml:1:"), std::string::npos);
}

}  // namespace
}  // namespace feran::test_html_report
