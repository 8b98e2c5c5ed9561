// Support files sit in the folder of the running executable or of
// libshadetree.so (installed, in lib/ beside bin/). Support modules are
// loaded from there on first use (libshadetree_image_io.so,
// libshadetree_vdb.so): each wraps a
// library whose dynamic linking would cost every command's start-up
// (OpenImageIO pulls in some 250 shared libraries, OpenVDB a few dozen
// milliseconds), behind a small C interface.
#pragma once

#include <string>

namespace shadetree {

// Where the support file `file` (a module, or the mesh reader program) is:
// in the first of the folders above that holds it, else the first folder.
std::string support_file_path(const std::string& file);

class LoadableModule {
 public:
  // `file` is the module's file name, `what` names it in messages.
  LoadableModule(const std::string& file, const std::string& what);

  // The function `name` of the module, or null (error() says why).
  template <class Function>
  Function* function(const char* name) {
    return reinterpret_cast<Function*>(symbol(name));
  }
  // Empty when the module and every function asked for were found.
  const std::string& error() const { return error_; }

 private:
  void* symbol(const char* name);
  void* handle_ = nullptr;
  std::string path_, what_, error_;
};

}  // namespace shadetree
