#pragma once
/// @file
/// Results for people: plain-text tables for the terminal.

#include <string>

#include <feran/analyses/campbell/campbell.hpp>
#include <feran/analyses/static/static_analysis.hpp>
#include <feran/analyses/transient/transient_analysis.hpp>
#include <feran/analyses/modal/modal.hpp>
#include <feran/io/result_writer.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// Table of a model's settable parameters: path, value with unit, meaning.
std::string parameters_report(const std::vector<Parameter>& parameters, const ResultSource& source);

}  // namespace feran
