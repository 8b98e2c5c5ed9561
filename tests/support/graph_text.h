// Builds small graph files in tests: a header and the given nodes/outputs.
#pragma once

#include <string>

namespace shadetree::testing {

inline std::string graph_text(const std::string& nodes, const std::string& outputs,
                              const std::string& extra = "", const std::string& kind = "texture") {
  return R"({"format": "shadetree-graph", "version": 1, "kind": ")" + kind + R"(", )" + extra +
         R"( "nodes": [)" + nodes + R"(], "outputs": {)" + outputs + "}}";
}

}  // namespace shadetree::testing
