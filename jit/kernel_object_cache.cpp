#include "jit/kernel_object_cache.h"

#include "platform/user_cache.h"

namespace shadetree {

void store_kernel_object(const std::filesystem::path& folder, const std::string& name, std::string_view object,
                         int limit) {
  store_in_cache(folder, name + ".o", object, "shade_kernel_", limit);
}

}  // namespace shadetree
