#pragma once
/// @file
/// The spec of a model-entry family (docs/model-format.md); its field table and build
/// step are in src/spec/entries/journal_bearings.cpp.

#include <optional>
#include <string>

#include <feran/core/types.hpp>
#include <feran/spec/node_ref.hpp>

namespace feran {

/// [[journal_bearings]]: a plain journal bearing on an oil film.
struct JournalBearingSpec {
  std::string name;
  NodeRef node;                                           ///< the journal
  std::optional<NodeRef> to;                              ///< the housing; not given (or "ground"): the ground
  Real diameter = 0.0;                                    ///< D [m]
  Real length = 0.0;                                      ///< L [m]
  Real clearance = 0.0;                                   ///< radial clearance c [m]
  Real viscosity = 0.0;                                   ///< μ [Pa s]
  std::string theory = "short";                           ///< "short" (Ocvirk), "long" (Sommerfeld) or "finite"
  std::optional<std::string> cavitation;                  ///< "reynolds" or "gumbel" (finite only)
  std::optional<int> circumferential_cells, axial_cells;  ///< the finite bearing's grid
  std::optional<std::string> evaluation;                  ///< "auto", "table" or "exact" (finite only)
  bool operator==(const JournalBearingSpec&) const = default;
};

}  // namespace feran
