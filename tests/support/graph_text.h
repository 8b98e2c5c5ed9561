// Builds small graph files in tests: a header and the given nodes/outputs.
#pragma once

#include <string>

namespace shadetree::testing {

// A volume graph without a render section in `extra` gets the unit cube
// as its bounds, which every volume needs to be checked.
inline std::string graph_text(const std::string& nodes, const std::string& outputs,
                              const std::string& extra = "", const std::string& kind = "texture") {
  const bool bounds = kind == "volume" && extra.find("\"render\"") == std::string::npos;
  return R"({"format": "shadetree-graph", "version": 1, "kind": ")" + kind + R"(", )" + extra +
         (bounds ? R"( "render": {"volume": {"bounds": {"min": [0, 0, 0], "max": [1, 1, 1]}}},)" : "") +
         R"( "nodes": [)" + nodes + R"(], "outputs": {)" + outputs + "}}";
}

}  // namespace shadetree::testing
