// The node library as JSON, for the editor's palette: every op with its
// family, doc, typed inputs (defaults, docs), outputs, attributes and the
// graph kinds it may be used in; and each graph kind with its doc and
// output contract (nodes/output_contract.h) and the render fields it takes.
// Generated from the registry, the same
// that writes docs/nodes.md.
#pragma once

#include <nlohmann/json.hpp>

namespace shadetree {

nlohmann::json node_library_json();

}  // namespace shadetree
