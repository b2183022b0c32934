// The report's data: the rotor's mass properties against the closed forms of a
// uniform shaft, the sections present for what the model gives, text that would end
// the data's <script> element kept inside it, and the configuration file's located
// errors. (The page itself is checked in a browser: tests/browser/.)
#include <algorithm>
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

// The verdict of each check, by name.
const nlohmann::json& verdict(const nlohmann::json& d, const std::string& check) {
  for (const nlohmann::json& v : d["verdicts"])
    if (v["check"] == check) return v;
  ADD_FAILURE() << "no verdict " << check;
  return d["verdicts"][0];
}

TEST(HtmlReport, RunsTheApi684SectionWhenTheModelGivesAnOperatingRange) {
  // Also the verdicts it opens with: the stability and separation verdicts say what
  // the API section says; a rotor on springs has no bearing model to judge loads or
  // films by ("not checked", with the reason).
  if (!report_available()) GTEST_SKIP() << "built without plotly.js";
  const ModelFile file = read_model_string(
      shaft_model("shaft",
                  "[api684]\nmin_speed = \"2000 rpm\"\nmax_speed = \"3000 rpm\"\npoints = 41\nmap_points = 5\n"),
      "shaft.toml");
  ReportOptions options;
  options.runup = false;
  options.n_threads = 1;
  std::string text;
  const nlohmann::json d = report_data(html_report(file, options, &text));
  ASSERT_TRUE(d.contains("api684"));
  EXPECT_FALSE(d["api684"].contains("error"));
  EXPECT_EQ(d["api684"]["map"]["stiffness_n_per_m"].size(), 5u);
  EXPECT_NEAR(d["operating"]["max_rpm"].get<Real>(), 3000, 1e-9);
  ASSERT_EQ(d["verdicts"].size(), 5u);
  EXPECT_EQ(verdict(d, "stability in the operating range")["status"],
            d["api684"]["operating_stability"]["passes"] ? "pass" : "FAIL");
  EXPECT_EQ(verdict(d, "separation margins")["status"], d["api684"]["separation_margins_pass"] ? "pass" : "FAIL");
  EXPECT_EQ(verdict(d, "bearing loads")["status"], "not checked");
  EXPECT_EQ(verdict(d, "minimum film thickness")["status"], "not checked");
  EXPECT_NE(text.find("separation margins"), std::string::npos);
  options.speed_unit = "rad/s";
  EXPECT_THROW(html_report(file, options), Error);
}

TEST(HtmlReport, JudgesTheJournalBearingsFilmAndLoadByTrumplersLimits) {
  // The two-disk rotor on short journal bearings (unstable from about 5300 rpm, run
  // from 8000 to 10000 rpm): the stability verdict fails as API 684's does, and the
  // film and load verdicts carry the static section's own numbers against limits
  // computed here from the bearings' size (D = 60 mm, L = 30 mm):
  // h_min ≥ 5.08 µm + 4e-5·D = 7.48 µm, W/(L·D) ≤ 300 psi.
  if (!report_available()) GTEST_SKIP() << "built without plotly.js";
  const ModelFile file = read_model_file(FERAN_TEST_MODELS "/valid/journal_rotor.toml");
  ReportOptions options;
  options.runup = false;
  options.n_threads = 1;
  options.api684_request.points = 41;
  options.api684_request.map_points = 5;
  const nlohmann::json d = report_data(html_report(file, options));
  EXPECT_EQ(verdict(d, "stability in the operating range")["status"], "FAIL");
  EXPECT_FALSE(d["api684"]["operating_stability"]["passes"].get<bool>());
  double thinnest = 1e300, heaviest = 0;
  for (const nlohmann::json& b : d["static"]["supports"]) {
    thinnest = std::min(thinnest, b["operating"]["min_film_thickness_m"].get<double>());
    heaviest = std::max(heaviest, b["operating"]["load_n"].get<double>() / (0.03 * 0.06));
  }
  const nlohmann::json& film = verdict(d, "minimum film thickness");
  EXPECT_NEAR(film["value"].get<double>(), thinnest * 1e6, 1e-12 * thinnest * 1e6);
  EXPECT_EQ(film["status"], thinnest >= 5.08e-6 + 4e-5 * 0.06 ? "pass" : "FAIL");
  EXPECT_NE(film["reason"].get<std::string>().find("7.48 µm"), std::string::npos) << film["reason"];
  const nlohmann::json& load = verdict(d, "bearing loads");
  EXPECT_NEAR(load["value"].get<double>(), heaviest * 1e-6, 1e-9 * heaviest * 1e-6);
  EXPECT_EQ(load["status"], heaviest <= 300 * 6894.757 ? "pass" : "FAIL");
  EXPECT_NE(load["reason"].get<std::string>().find("unstable"), std::string::npos) << load["reason"];
}

TEST(ReportConfig, ReadsItsKeysAndLocatesMistakes) {
  const ModelFile file = read_model_string(shaft_model("shaft"), "shaft.toml");
  ReportOptions options;
  read_report_config(
      "title = \"T\"\nspeed_unit = \"Hz\"\n[campbell]\nstop = \"50 Hz\"\n[modes]\nspeeds = [0, \"10 Hz\"]\n"
      "[response]\nprobes = [\"left\", 5]\n[runup]\nenabled = false\n"
      "[orbits]\nfrom = \"10 Hz\"\nto = \"20 Hz\"\nstart_at = \"15 Hz\"\nprobes = [\"left\"]\n",
      "report.toml", file.model, options);
  EXPECT_EQ(options.title, "T");
  EXPECT_EQ(options.speed_unit, "Hz");
  EXPECT_NEAR(*options.campbell.stop, 2 * pi * 50, 1e-9);
  ASSERT_EQ(options.mode_speeds.size(), 2u);
  EXPECT_NEAR(options.mode_speeds[1], 2 * pi * 10, 1e-9);
  ASSERT_EQ(options.response.probes.size(), 2u);  // the nodes at indices 0 and 4
  EXPECT_EQ(node_index(file.model, options.response.probes[0]), 0);
  EXPECT_EQ(node_index(file.model, options.response.probes[1]), 4);
  EXPECT_FALSE(options.runup);
  EXPECT_TRUE(options.orbits);
  EXPECT_NEAR(*options.orbits_request.to, 2 * pi * 20, 1e-9);
  EXPECT_EQ(options.orbits_request.start_at, "15 Hz");
  ASSERT_EQ(options.orbits_request.probes.size(), 1u);
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
  EXPECT_NE(message("[orbits]\nstart_a = \"15 Hz\"\n").find("did you mean 'start_at'"), std::string::npos);
  EXPECT_NE(message("[orbits]\nenabled = true\nprobes = [\"middle\"]\n").find("report.toml:3:"), std::string::npos);
  EXPECT_NE(message("[orbits]\nsettle = \"-1 s\"\n").find("report.toml:2:"), std::string::npos);
  EXPECT_NE(message("[modes]\nspeeds = [\"-5 Hz\"]\n").find("report.toml:2:"), std::string::npos);
  EXPECT_NE(message("[study]\ndirectory = \"nowhere\"\n").find("does not exist"), std::string::npos);
  EXPECT_NE(message("title = \n").find("report.toml:1:"), std::string::npos);
}

}  // namespace
}  // namespace feran::test_html_report
