#include "render/loadable_module.h"

#include <dlfcn.h>

#include <filesystem>

namespace shadetree {

LoadableModule::LoadableModule(const std::string& file, const std::string& what) : what_(what) {
  std::error_code error;
  const auto folder = std::filesystem::read_symlink("/proc/self/exe", error).parent_path();
  path_ = (folder / file).string();
  handle_ = ::dlopen(path_.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle_) {
    const char* reason = ::dlerror();
    error_ = "cannot load " + what_ + " (" + path_ + "): " + (reason ? reason : "unknown error");
  }
}

void* LoadableModule::symbol(const char* name) {
  if (!handle_) return nullptr;
  void* found = ::dlsym(handle_, name);
  if (!found && error_.empty()) error_ = what_ + " module " + path_ + " is incomplete (no " + name + ")";
  return found;
}

}  // namespace shadetree
