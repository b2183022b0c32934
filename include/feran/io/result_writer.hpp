#pragma once
/// @file
/// Results for programs: JSON and CSV (format in docs/output-format.md).

#include <string>
#include <vector>

#include <feran/analyses/api684/api684_analysis.hpp>
#include <feran/analyses/campbell/campbell.hpp>
#include <feran/analyses/static/static_analysis.hpp>
#include <feran/analyses/modal/modal.hpp>
#include <feran/model/model.hpp>
#include <feran/io/result_source.hpp>
#include <feran/spec/parameters.hpp>

namespace feran {

/// JSON text of a model's settable parameters (feran params).
std::string parameters_json(const std::vector<Parameter>& parameters, const ResultSource& source);

}  // namespace feran
