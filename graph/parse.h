// Stage 1: JSON text -> Graph. Checks the file's structure (fields, their
// JSON types, the version); the meaning of names and types is check's job.
#pragma once

#include <string>

#include "graph/diagnostic.h"
#include "graph/graph.h"

namespace shadetree {

// Limits on what a graph file may hold (see also lower.h:
// max_program_instructions, and check.h: max_function_nesting).
inline constexpr std::size_t max_graph_file_bytes = 16u << 20;
inline constexpr std::size_t max_nodes_per_graph = 100000;
inline constexpr int max_image_side = 16384;
// Frames are whole numbers from 0 to this, and a sequence (a graph's
// render.frames, a --frames list) holds at most max_sequence_frames.
inline constexpr long long largest_frame = 1000000000;
inline constexpr int max_sequence_frames = 100000;

// `file` names the graph in messages.
Result<Graph> parse_graph(const std::string& json_text, const std::string& file);
Result<Graph> load_graph(const std::string& path);

}  // namespace shadetree
