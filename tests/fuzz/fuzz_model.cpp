// Fuzzing harness: reader, builder and checks, then what a user does with a small
// model that passes them: a modal analysis (dense, all modes), a static deflection,
// and every writer (JSON, CSV, the terminal table, the model written back as TOML).
// Invariants beyond "no crash": the TOML written reads back to an equal spec, and a
// valid model's results are written without an exception. Any exception other than
// feran::Error is a defect (abort). docs/fuzzing.md says how to run it.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string_view>

#include <feran/analyses/modal/analysis.hpp>
#include <feran/analyses/settings.hpp>
#include <feran/analyses/static/analysis.hpp>
#include <feran/core/error.hpp>
#include <feran/forces/finite_bearing.hpp>
#include <feran/io/model_reader.hpp>
#include <feran/io/model_writer.hpp>
#include <feran/io/report.hpp>
#include <feran/io/result_writer.hpp>

namespace {

// Larger models are read and checked but not analysed: the harness looks for defects
// of the code, and a dense eigen solve of thousands of DOFs only slows it down.
constexpr feran::Index max_analysed_dofs = 300;
// Likewise finite-length bearings on finer grids than this in all (the default grid
// has 576 cells): the format allows 250 000 cells a bearing, and under the sanitizers
// one static and one modal analysis took 100 s on two bearings of 5000 × 50 cells
// (CI's fuzzing run stopped at libFuzzer's 30 s timeout on such an input) and 13 s on
// one of 89 × 44. The film solver is the same code at every size, and the seeds' grids
// exercise it.
constexpr long long max_analysed_film_cells = 2500;

long long finite_film_cells(const feran::ModelSpec& spec) {
  const feran::FiniteBearingGrid defaults;
  long long cells = 0;
  for (const auto& bearing : spec.journal_bearings)
    if (bearing.theory == "finite")
      cells += static_cast<long long>(bearing.circumferential_cells.value_or(defaults.circumferential)) *
               bearing.axial_cells.value_or(defaults.axial);
  return cells;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace feran;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  ModelFile file;
  try {
    file = read_model_string(text, "fuzz.toml");
  } catch (const Error&) {
    return 0;  // a bad model, refused with a message
  }
  // The model written back reads as the same spec.
  try {
    if (!(read_model_spec(write_toml(file.spec), "written.toml") == file.spec)) std::abort();
  } catch (const Error&) {
    std::abort();
  }
  if (file.model.n_dofs() > max_analysed_dofs || finite_film_cells(file.spec) > max_analysed_film_cells) return 0;
  const ResultSource source{file.path, file.title};
  try {
    const std::shared_ptr<const ModelFile> unowned(std::shared_ptr<const ModelFile>(), &file);
    ModalSpec request;
    request.solver = "dense";
    request.shapes = true;
    const Outcome<ModalAnalysis> o = run_analysis<ModalAnalysis>(unowned, request, file_key_name<ModalAnalysis>());
    (void)ModalAnalysis::json(o);
    (void)ModalAnalysis::csv(o);
    (void)ModalAnalysis::terminal(o);
  } catch (const Error&) {
  }
  try {
    const std::shared_ptr<const ModelFile> unowned(std::shared_ptr<const ModelFile>(), &file);
    const Outcome<StaticAnalysis> o = run_analysis<StaticAnalysis>(unowned, {}, file_key_name<StaticAnalysis>());
    if (o.result.info.converged()) {
      (void)StaticAnalysis::json(o);
      (void)StaticAnalysis::csv(o);
      (void)StaticAnalysis::terminal(o);
    }
  } catch (const Error&) {
  }
  return 0;
}
