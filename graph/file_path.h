// The path policy every file the project opens or writes goes through
// first, whoever names it (a graph, the command line, an editor request):
// a path is text a person could type. NUL (which would cut the path where
// the system sees it, after the checks have seen all of it), other control
// characters and over-long names are refused before any file is touched.
#pragma once

#include <string>

#include "graph/diagnostic.h"

namespace shadetree {

inline constexpr std::size_t max_path_bytes = 4096;       // PATH_MAX on Linux
inline constexpr std::size_t max_file_name_bytes = 255;  // NAME_MAX on Linux

// Why `path` may not be used, or success. `what` names it in the message
// ("output", "mesh file", ...); the diagnostic is an invalid_input one
// (exit status 2, HTTP 400) and shows the path escaped and shortened.
Status check_path_text(const std::string& path, const std::string& what);

}  // namespace shadetree
