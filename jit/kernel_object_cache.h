// The disk cache of compiled kernels: each kernel's object file under its
// name in the user's cache folder (platform/user_cache.h), so that a
// second run of the same graph skips compilation; the JIT touches what it
// reads, so the kernels least recently used go first.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace shadetree {

// Keeps `object` as NAME.o in `folder`, then prunes the folder to `limit`
// objects.
void store_kernel_object(const std::filesystem::path& folder, const std::string& name, std::string_view object,
                         int limit);

}  // namespace shadetree
