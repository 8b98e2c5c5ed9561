#include "platform/loadable_module.h"

#include <dlfcn.h>

#include <filesystem>
#include <vector>

namespace shadetree {

namespace {

// Where modules may be: the folder of the file holding this code (the
// executable, or libshadetree.so for a program using the library), then,
// for an installed executable, the lib folder beside its bin folder.
std::vector<std::filesystem::path> module_folders() {
  std::vector<std::filesystem::path> folders;
  Dl_info info{};
  if (::dladdr(reinterpret_cast<void*>(&module_folders), &info) != 0 && info.dli_fname && info.dli_fname[0] == '/')
    folders.push_back(std::filesystem::path(info.dli_fname).parent_path());
  std::error_code error;
  const auto executable = std::filesystem::read_symlink("/proc/self/exe", error).parent_path();
  if (!error) {
    folders.push_back(executable);
    folders.push_back(executable.parent_path() / "lib");
  }
  return folders;
}

}  // namespace

std::string support_file_path(const std::string& file) {
  const std::vector<std::filesystem::path> folders = module_folders();
  for (const auto& folder : folders) {
    std::error_code error;
    if (std::filesystem::exists(folder / file, error)) return (folder / file).string();
  }
  return folders.empty() ? file : (folders.front() / file).string();
}

LoadableModule::LoadableModule(const std::string& file, const std::string& what)
    : path_(support_file_path(file)), what_(what) {
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
