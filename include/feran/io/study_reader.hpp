#pragma once
/// @file
/// Reads a study file (docs/study-format.md): the base model, the settings applied
/// to it, design variables, quantities, objectives, constraints and the exploration.
/// Every problem is a ModelError at the file, line and column where it was written,
/// found before any design is evaluated: unknown keys, parameter paths that name
/// nothing, values of the wrong kind, objectives naming no quantity.

#include <string>
#include <string_view>

#include <feran/io/model_reader.hpp>
#include <feran/study/study.hpp>

namespace feran {

struct StudyFile {
  StudySpec study;
  ModelFile base;    ///< the base model as read (before the study's settings)
  std::string path;  ///< the study file's path
};

/// Reads the study at @p path; the model it names is read relative to the study
/// file's directory and checked with the study's settings applied.
StudyFile read_study_file(const std::string& path);

/// Reads a study from TOML text; @p path names it in messages, and relative model
/// paths are taken from its directory.
StudyFile read_study_string(std::string_view toml_text, const std::string& path);

/// What a study built in code (the Python package's feran.Study) has that a study
/// file does not: its base model, given instead of the file's 'model' key (which it
/// must not have), and quantities of kind "function", whose code the caller attaches
/// to QuantitySpec::function after reading.
struct StudyCode {
  ModelFile base;
  std::string model_name;  ///< how outputs name the base model (StudySpec::model_path)
};

/// Reads a study built in code from TOML text (@p path names it in messages).
StudyFile read_study_string(std::string_view toml_text, const std::string& path, const StudyCode& code);

}  // namespace feran
