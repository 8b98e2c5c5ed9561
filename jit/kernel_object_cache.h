// The disk cache of compiled kernels: each kernel's object file under its
// name in a user cache folder, so that a second run of the same graph
// skips compilation. Objects are written to a temporary file and renamed,
// so a second process never reads half of one, and the folder is bounded,
// the least recently used (written, or read: the JIT touches what it
// reads) going first. A cache that cannot be written is only a missed
// speed-up.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace shadetree {

// `configured` if not empty, else $SHADETREE_CACHE_DIR, else
// $XDG_CACHE_HOME/shadetree, else ~/.cache/shadetree; empty without HOME.
std::filesystem::path kernel_cache_folder(const std::string& configured);

// Keeps `object` as NAME.o in `folder`, then prunes the folder to `limit`
// objects.
void store_kernel_object(const std::filesystem::path& folder, const std::string& name, std::string_view object,
                         int limit);

}  // namespace shadetree
