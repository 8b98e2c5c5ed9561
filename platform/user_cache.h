// The user's cache folder, where shadetree keeps what is costly to make
// and cheap to read again (compiled kernels, meshes' distance grids).
// Files are written to a temporary file and renamed, so a second process
// never reads half of one, and each kind is bounded, the least recently
// used (written, or touched by its reader) going first. A cache that
// cannot be written is only a missed speed-up.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace shadetree {

// `configured` if not empty, else $SHADETREE_CACHE_DIR, else
// $XDG_CACHE_HOME/shadetree, else ~/.cache/shadetree; empty without HOME.
std::filesystem::path user_cache_folder(const std::string& configured);

// Keeps `bytes` as `folder`/`name`, then removes the least recently used
// files named like it (`kind`, a prefix, and its extension) past `limit`.
void store_in_cache(const std::filesystem::path& folder, const std::string& name, std::string_view bytes,
                    const std::string& kind, int limit);

}  // namespace shadetree
