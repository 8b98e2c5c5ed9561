// Output files (images, VDB files) are written to a temporary file in the
// target's folder and renamed over the target only once complete, so that
// a failed or interrupted command never leaves a partial file behind.
#pragma once

#include <functional>
#include <string>

#include "graph/diagnostic.h"

namespace shadetree {

// Whether `path`'s folder exists: checked before any work is done for it.
Status check_output_folder(const std::string& path);

// write(temporary) writes the file to `temporary` and returns why it could
// not, or "" on success; then the file is renamed to `path`. The temporary
// name is unique to the call, so concurrent writes of one path each finish
// whole (the last rename wins), and keeps `path`'s extension, by which
// some writers choose a format.
Status write_then_rename(const std::string& path, const std::function<std::string(const std::string&)>& write);

}  // namespace shadetree
