#pragma once
/// @file
/// The list of analyses: every front end (the command line, the Python module) offers
/// each analysis listed here, from its face (analyses/analysis.hpp). A new analysis is
/// a folder under analyses/ and one entry in this list.

#include <feran/analyses/analysis.hpp>
#include <feran/analyses/api684/analysis.hpp>
#include <feran/analyses/campbell/analysis.hpp>
#include <feran/analyses/modal/analysis.hpp>
#include <feran/analyses/periodic/analysis.hpp>
#include <feran/analyses/response/analysis.hpp>
#include <feran/analyses/runup/analysis.hpp>
#include <feran/analyses/static/analysis.hpp>

namespace feran {

/// A list of analysis faces; for_each calls f.template operator()<A>() for each.
template <AnalysisFace... A>
struct AnalysisList {
  template <class F>
  static void for_each(F&& f) {
    (f.template operator()<A>(), ...);
  }
};

/// The analyses, in the order the command line's help lists them after the ones not
/// yet moved into their folders.
using Analyses = AnalysisList<ModalAnalysis, CampbellAnalysis, ResponseAnalysis, StaticAnalysis, RunupAnalysis,
                              Api684Analysis, OrbitsAnalysis>;

}  // namespace feran
