// Fuzzing harness: the model reader alone, TOML text to a ModelSpec, on any bytes.
// Every input must end in a ModelSpec or a feran::Error (a located message); any
// other exception, a crash, a sanitizer report or a hang is a defect. Built with
// libFuzzer (clang, FERAN_FUZZ=ON) or, for the regression inputs under ctest, with
// replay_main.cpp. docs/fuzzing.md says how to run it.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include <feran/core/error.hpp>
#include <feran/io/model_reader.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    feran::SpecSource source;
    (void)feran::read_model_spec(text, "fuzz.toml", &source);
  } catch (const feran::Error&) {
    // A bad model: what the reader is for.
  }
  return 0;
}
