// Support modules loaded on first use from the folder of the running
// executable or of libshadetree.so (libshadetree_image_io.so,
// libshadetree_vdb.so; installed, from lib/ beside bin/): each wraps a
// library whose dynamic linking would cost every command's start-up
// (OpenImageIO pulls in some 250 shared libraries, OpenVDB a few dozen
// milliseconds), behind a small C interface.
#pragma once

#include <string>

namespace shadetree {

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
