// Graph files as JSON documents, read in time linear in their size.
// nlohmann's ordered_json (which keeps a file's member order: a function's
// first output is the first written) finds a key by a linear search, so
// its parser built an object of n members in n^2 time: 200k params took
// 53 s, and a 16 MiB file of one object never finished. This reader
// builds the same document with one hash lookup per member, and refuses
// what the format never needs: a key written twice in one object (which
// nlohmann silently let the last win) and nesting deeper than
// max_json_depth (which would overflow the stack).
#pragma once

#include <string>

#include "graph/diagnostic.h"
#include "graph/json_reader.h"

namespace shadetree {

inline constexpr int max_json_depth = 64;

// The document of `text`, or why it is not one; `file` names it in the
// diagnostic ("invalid JSON: ..." with the line and column where known).
Result<json> parse_json_document(const std::string& text, const std::string& file);

}  // namespace shadetree
