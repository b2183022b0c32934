#pragma once
/// @file
/// Node and probe references written outside a model file (command-line options
/// such as --probe), resolved against a model with the model reader's suggestions.

#include <optional>
#include <string>
#include <utility>

#include <feran/core/error.hpp>
#include <feran/core/types.hpp>
#include <feran/model/model.hpp>

namespace feran {

/// The index (in model.nodes) of the node that @p text refers to.
///
/// Text made only of the digits 0-9 ("7") is a node number; if no node has that
/// number but a node is named so, that node is taken. Any other text is a node
/// name (exact, case-sensitive). @p what names the reference in messages, e.g.
/// "--probe". Throws feran::Error when no node matches, e.g.
/// "--probe 'rotr': no such node; did you mean 'rotor'?" (same suggestion rule as
/// the model reader: a name equal ignoring case or within 2 edits), or, when no
/// name is close, a message listing the node names (up to 8) and numbers.
Index find_node_reference(const Model& model, const std::string& text, const std::string& what);

/// Parses a probe: a node reference alone ("rotor", "7"), or followed by ':' and a
/// DOF name ("rotor:v", "7:rz"; DOF names u, v, w, rx, ry, rz as in dof_name()).
/// Returns the node index and the DOF (std::nullopt when none is given). A node
/// name that itself contains ':' is matched whole first. Throws feran::Error for an
/// unknown node (as find_node_reference() with what = "probe") or DOF, e.g.
/// "probe 'rotor:y': unknown DOF 'y'; the DOFs are u, v, w, rx, ry and rz (did you
/// mean 'v', the displacement along y?)".
std::pair<Index, std::optional<Dof>> parse_probe(const Model& model, const std::string& text);

}  // namespace feran
