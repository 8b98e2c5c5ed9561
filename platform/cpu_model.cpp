#include "platform/cpu_model.h"

#include <fstream>

namespace shadetree {

std::string cpu_model_name() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);)
    if (line.rfind("model name", 0) == 0) {
      const std::size_t colon = line.find(':');
      const std::size_t name = colon == std::string::npos ? colon : line.find_first_not_of(" \t", colon + 1);
      if (name != std::string::npos) return line.substr(name);
    }
  return "an unnamed CPU";
}

}  // namespace shadetree
