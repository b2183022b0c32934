// Tests of io/result_writer beyond the documented keys (tests/cli checks those).
#include <feran/analyses/modal/analysis.hpp>
#include <feran/io/result_writer.hpp>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <memory>
#include <string>

#include "test_models.hpp"

namespace feran::test_result_writer {
namespace {

// A model path with a byte that is not UTF-8 (any bytes can name a file) made the
// JSON writer throw after the whole analysis had run, leaving no JSON (exit 4). The
// byte is written as U+FFFD and the document stays strict JSON.
TEST(ResultWriter, PathThatIsNotUtf8GivesValidJson) {
  auto file = std::make_shared<ModelFile>();
  file->model = test::friswell_5_9_1();
  const ModalResult result = run_modal(file->model, 0.0);
  const ResultSource source{"models/rotor\xff\xfe.toml", "title", {}};
  const Outcome<ModalAnalysis> o{file, {}, result, source};
  std::string text;
  ASSERT_NO_THROW(text = ModalAnalysis::json(o));
  nlohmann::json j;
  ASSERT_NO_THROW(j = nlohmann::json::parse(text));  // the parser rejects invalid UTF-8
  EXPECT_EQ(j["model"]["path"].get<std::string>(), "models/rotor\xef\xbf\xbd\xef\xbf\xbd.toml");
}

}  // namespace
}  // namespace feran::test_result_writer
