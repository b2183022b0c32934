// Every fixture in tests/models/invalid/ must be rejected with a ModelError at the
// line, and with a message matching the regular expression, stated in its first
// two lines:
//
//   # error-line: N
//   # error-match: <ECMAScript regex, searched in ModelError::message()>

#include <feran/io/model_reader.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

#include <sys/stat.h>
#include <unistd.h>
#include <ostream>
#include <regex>
#include <string>
#include <vector>

namespace feran::test_model_reader_errors {
namespace {

namespace fs = std::filesystem;

struct InvalidFixture {
  std::string name;  ///< file stem, also the test's name
  std::string path;
};

// Names the fixture in gtest's output instead of dumping its bytes.
void PrintTo(const InvalidFixture& fixture, std::ostream* os) { *os << fixture.path; }

std::vector<InvalidFixture> invalid_fixtures() {
  std::vector<InvalidFixture> out;
  for (const auto& entry : fs::directory_iterator(fs::path(FERAN_TEST_MODELS) / "invalid"))
    if (entry.path().extension() == ".toml") out.push_back({entry.path().stem().string(), entry.path().string()});
  std::sort(out.begin(), out.end(), [](const InvalidFixture& a, const InvalidFixture& b) { return a.name < b.name; });
  return out;
}

struct Expectation {
  int line = 0;
  std::string pattern;
};

Expectation read_expectation(const std::string& path) {
  std::ifstream in(path);
  std::string first, second;
  std::getline(in, first);
  std::getline(in, second);
  const std::string line_tag = "# error-line: ", match_tag = "# error-match: ";
  Expectation e;
  if (first.rfind(line_tag, 0) == 0) e.line = std::stoi(first.substr(line_tag.size()));
  if (second.rfind(match_tag, 0) == 0) e.pattern = second.substr(match_tag.size());
  return e;
}

class InvalidModel : public ::testing::TestWithParam<InvalidFixture> {};

TEST_P(InvalidModel, IsRejectedAtTheStatedLineWithTheStatedMessage) {
  const InvalidFixture& fixture = GetParam();
  const Expectation expected = read_expectation(fixture.path);
  ASSERT_GT(expected.line, 0) << fixture.path << ": first line must be '# error-line: N'";
  ASSERT_FALSE(expected.pattern.empty()) << fixture.path << ": second line must be '# error-match: <regex>'";
  const std::regex pattern(expected.pattern, std::regex::ECMAScript);

  try {
    (void)read_model_file(fixture.path);
    FAIL() << fixture.path << " was accepted";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.where().file, fixture.path);
    EXPECT_EQ(e.where().line, expected.line) << e.what();
    EXPECT_GE(e.where().column, 1) << e.what();
    EXPECT_TRUE(std::regex_search(e.message(), pattern))
        << "message: " << e.message() << "\npattern: " << expected.pattern;
    // what() is "file:line:column: message", the form compilers use.
    EXPECT_EQ(std::string(e.what()), fixture.path + ":" + std::to_string(e.where().line) + ":" +
                                         std::to_string(e.where().column) + ": " + e.message());
  }
}

std::string fixture_test_name(const ::testing::TestParamInfo<InvalidFixture>& param_info) {
  std::string name = param_info.param.name;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Fixtures, InvalidModel, ::testing::ValuesIn(invalid_fixtures()), fixture_test_name);

// The error classes the reader promises to report; each must keep a fixture.
TEST(InvalidModelFixtures, CoverEveryErrorClass) {
  const std::vector<std::string> required = {
      "syntax_error", "unknown_key", "missing_key", "wrong_type", "wrong_unit", "negative_length", "inner_not_smaller",
      "unknown_node", "unknown_material", "duplicate_node_name", "bad_coefficient_law", "zero_mass",
      "singular_stiffness", "conflicting_rigid_body",
      // Loads, loss factors and the [response] and [static] defaults.
      "force_missing_amplitude", "force_direction_for_rotating", "force_bad_direction", "rotating_force_on_stator",
      "response_unknown_probe", "static_g_with_none", "static_bad_gravity", "static_load_no_component",
      "negative_loss_factor",
      // The [runup] defaults.
      "runup_mixed_profile_forms", "runup_table_not_increasing", "runup_table_not_at_zero", "runup_negative_speed",
      "runup_unknown_integrator", "runup_unknown_spring", "runup_unnamed_spring", "runup_zero_dt"};
  std::vector<std::string> present;
  for (const InvalidFixture& f : invalid_fixtures()) present.push_back(f.name);
  for (const std::string& name : required)
    EXPECT_NE(std::find(present.begin(), present.end(), name), present.end())
        << "missing fixture tests/models/invalid/" << name << ".toml";
}

// [runup] errors beyond the fixtures: each case is a [runup] table (and springs)
// appended to a clamped shaft with nodes 1-3, rejected at the stated line of the
// appended text with a message matching the stated expression.
TEST(ModelReaderErrors, RunupProblemsAreLocatedAndExplained) {
  const std::string base = R"([[materials]]
name = "steel"
E = 2.1e11
nu = 0.3
rho = 7850

[[shafts]]
material = "steel"
sections = [{ length = 0.1, outer_diameter = 0.02, elements = 2 }]

[[fixed]]
node = 1

[[fixed]]
node = 3

[[springs]]
name = "bearing"
node = 2
ky = 1e5

[[springs]]
name = "bearing"
node = 2
kz = 1e5

[[springs]]
name = "seal"
node = 2
cy = 10
)";
  const int base_lines = static_cast<int>(std::count(base.begin(), base.end(), '\n'));
  struct Case {
    const char* text;
    int line;  ///< in text, from 1
    const char* pattern;
  };
  const std::vector<Case> cases = {
      {"[runup]\ntable = [[0, 0]]\nramp_time = 1\nspeed = 3\n", 3,
       "^the speed profile .* mixes 'table' and 'ramp_time'$"},
      {"[runup]\nfrom = \"10 Hz\"\nramp_time = \"2 s\"\n", 1,
       "^missing key 'to' in \\[runup\\] \\(expected the ramp's final speed, a speed"},
      {"[runup]\nto = \"10 Hz\"\n", 1,
       "^missing key 'ramp_time' in \\[runup\\] \\(expected the ramp's duration, a time"},
      {"[runup]\nto = \"10 Hz\"\nramp_time = 0\n", 3, "^'ramp_time' must be positive, got 0 s$"},
      {"[runup]\nfrom = -1\nto = 1\nramp_time = 1\n", 2, "^'from' must not be negative, got -1 rad/s$"},
      {"[runup]\nspeed = \"-3 Hz\"\n", 2, "^'speed' must not be negative, got -3 Hz$"},
      {"[runup]\ntable = []\n", 2, "^'table' needs at least one \\[time, speed\\] pair"},
      {"[runup]\ntable = [[0, 0], [1, 2, 3]]\n", 2,
       "^each entry of 'table' must be a \\[time, speed\\] pair .*, got an array of 3 values$"},
      {"[runup]\ntable = [[0, 0],\n  [1, \"-5 Hz\"]]\n", 3, "^'table\\[1\\]\\[1\\]' must not be negative, got -5 Hz$"},
      {"[runup]\ntable = [[0, \"5 kg\"]]\n", 2, "^'table\\[0\\]\\[1\\]' has unit 'kg', expected a speed"},
      {"[runup]\nduration = \"-1 s\"\n", 2, "^'duration' must be positive, got -1 s$"},
      {"[runup]\noutput_interval = 0\n", 2, "^'output_interval' must be positive, got 0 s$"},
      {"[runup]\nrel_tol = 0\n", 2, "^'rel_tol' must be positive, got 0$"},
      {"[runup]\nmodes = 0\n", 2, "^'modes' must be at least 1, got 0$"},
      {"[runup]\nmodes = 2.5\n", 2, "^'modes' must be an integer, got a floating-point number"},
      {"[runup]\nabs_tol = \"1e-9 m\"\n", 2, "^'abs_tol' must be a number without unit"},
      {"[runup]\nintegrator = \"euler\"\n", 2,
       "^'integrator' must be \"trapezoidal\", \"rk3\", \"wolfbrandt\" or \"ros34pw2\", "
       "got \"euler\"$"},
      {"[runup]\nramptime = 1\n", 2, "^unknown key 'ramptime' in \\[runup\\]; did you mean 'ramp_time'\\?$"},
      {"[runup]\nprobes = [2, 2]\n", 2, "^node 2 appears twice in 'probes'$"},
      {"[runup]\nsprings = [\"seal\", \"seal\"]\n", 2, "^spring 'seal' appears twice in 'springs'$"},
      {"[runup]\nsprings = [\"bearing\"]\n", 2,
       "^spring name 'bearing' is ambiguous: 2 \\[\\[springs\\]\\] entries have it"},
      {"[runup]\nsprings = [3]\n", 2, "^'springs\\[0\\]' must be the name of a spring .*, got an integer \\(3\\)$"},
      {"[runup]\nsprings = []\n", 2, "^'springs' must not be empty"},
      {"[runup]\nsprings = [\"thrust\"]\n", 2,
       "^spring 'thrust' does not exist; the named springs are 'bearing' and 'seal'$"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    try {
      (void)read_model_string(base + c.text, "runup.toml");
      ADD_FAILURE() << "accepted";
    } catch (const ModelError& e) {
      EXPECT_EQ(e.where().line, base_lines + c.line) << e.what();
      EXPECT_TRUE(std::regex_search(e.message(), std::regex(c.pattern))) << e.message();
    }
  }

  // Without any named spring, the message says that only named ones can be referenced.
  const std::string unnamed = R"([[materials]]
name = "steel"
E = 2.1e11
nu = 0.3
rho = 7850

[[shafts]]
material = "steel"
sections = [{ length = 0.1, outer_diameter = 0.02 }]

[[springs]]
node = 1
ky = 1e5

[runup]
springs = ["bearing"]
)";
  try {
    (void)read_model_string(unnamed, "unnamed.toml");
    ADD_FAILURE() << "accepted";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.where().line, 16) << e.what();
    EXPECT_EQ(e.message(),
              "spring 'bearing' does not exist; no [[springs]] entry has a 'name', "
              "and only named springs can be referenced");
  }
}

TEST(ModelReaderErrors, MissingFileIsAnErrorButNotAModelError) {
  const std::string path = std::string(FERAN_TEST_MODELS) + "/no/such/file.toml";
  try {
    (void)read_model_file(path);
    FAIL() << "expected an error";
  } catch (const ModelError&) {
    FAIL() << "a missing file has no line to point at";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

// Only regular files are read: a directory, a FIFO without a writer (which blocked
// forever) and a device such as /dev/zero (read until memory ran out) are refused
// with a message saying what they are, and so is a file above the size limit.
TEST(ModelReaderErrors, OnlyRegularFilesOfBoundedSize) {
  const fs::path dir = fs::temp_directory_path() / ("feran_reader_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path fifo = dir / "model.toml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const fs::path big = dir / "big.toml";
  { std::ofstream(big) << "title = \"x\"\n"; }
  fs::resize_file(big, max_model_file_bytes + 1);  // sparse: no disk used
  const std::vector<std::pair<std::string, std::string>> cases = {
      {dir.string(), "is a directory, not a model file"},
      {fifo.string(), "is not a regular file (a FIFO)"},
      {"/dev/zero", "is not a regular file (a character device)"},
      {big.string(), "model files are limited to 67108864 bytes (64 MiB)"}};
  for (const auto& [path, expected] : cases) {
    try {
      (void)read_model_file(path);
      ADD_FAILURE() << path << ": expected an error";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  }
  fs::remove_all(dir);
}

// Dotted keys and table headers of tens of thousands of parts overflowed the TOML
// parser's stack (a crash without a message); more than 64 parts is refused at the
// part where the limit is passed, before parsing.
TEST(ModelReaderErrors, KeysNestedTooDeeplyAreRefusedBeforeParsing) {
  std::string dotted, header = "title = \"t\"\n[", inline_table = "\n\nx = { ";
  for (int i = 0; i < 30000; ++i) dotted += "x.";
  dotted += "x = 1\n";
  for (int i = 0; i < 40000; ++i) header += "x.";
  header += "x]\n";
  for (int i = 0; i < 30000; ++i) inline_table += "x.";
  inline_table += "x = 1 }\n";
  for (const auto& [text, line] : {std::pair{dotted, 1}, std::pair{header, 2}, std::pair{inline_table, 3}}) {
    try {
      (void)read_model_spec(text, "deep.toml");
      ADD_FAILURE() << "expected a ModelError";
    } catch (const ModelError& e) {
      EXPECT_EQ(e.where().line, line);
      EXPECT_EQ(e.where().column, line == 1 ? 128 : line == 2 ? 129 : 134);  // the 65th part's dot
      EXPECT_NE(e.message().find("nesting too deep: a key of more than 64 parts"), std::string::npos) << e.message();
    }
  }
  // Dots in values and quoted keys do not count, nor numbers in a long array.
  std::string values = "title = \"a.b.c\"\n[options]\n";
  std::string numbers = "[runup]\ntable = [";
  for (int i = 0; i < 200; ++i) numbers += "[0.5, 1.5], ";
  numbers += "[2.5, 3.5]]\n";
  try {
    (void)read_model_spec(numbers, "numbers.toml");
  } catch (const ModelError& e) {
    EXPECT_EQ(e.message().find("nesting too deep"), std::string::npos) << e.message();
  }
  EXPECT_NO_THROW((void)read_model_spec(values, "values.toml"));
}

TEST(ModelReaderErrors, StringInputIsNamedInMessages) {
  try {
    (void)read_model_string("title = 3\n", "inline.toml");
    FAIL() << "expected a ModelError";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.where().file, "inline.toml");
    EXPECT_EQ(e.where().line, 1);
    EXPECT_EQ(e.where().column, 9);  // the value, after "title = "
    EXPECT_EQ(e.message(), "'title' must be a string, got an integer (3)");
  }
}

TEST(ModelReaderErrors, SyntaxErrorKeepsTomlPosition) {
  try {
    (void)read_model_string("title = \"x\"\n[options\n", "broken.toml");
    FAIL() << "expected a ModelError";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.where().line, 2);
    EXPECT_NE(e.message().find("TOML syntax error"), std::string::npos) << e.message();
  }
}

}  // namespace
}  // namespace feran::test_model_reader_errors
