#include "jit/host_target.h"

#include <llvm/ADT/StringMap.h>
#include <llvm/TargetParser/Host.h>
#include <llvm/TargetParser/SubtargetFeature.h>

namespace shadetree {

bool host_has(const char* feature) {
  static const auto features = llvm::sys::getHostCPUFeatures();
  auto found = features.find(feature);
  return found != features.end() && found->second;
}

int host_vector_width() {
  if (host_has("avx512f")) return 16;
  if (host_has("avx2")) return 8;
  return 4;
}

// Measured with `shadetree bench --gathers` (figures in docs/architecture.md):
// per-lane loads beat vgatherdps on the x86 parts we have, permutes over
// registers beat both where AVX-512 allows them, and byte permutes (VBMI)
// do the noise permutation cheaper still.
GatherStrategy host_gather_strategy() {
  if (host_vector_width() < 16) return GatherStrategy::per_lane;
  return host_has("avx512vbmi") ? GatherStrategy::in_register_byte_permutes : GatherStrategy::in_register;
}

std::string host_cpu_name() { return llvm::sys::getHostCPUName().str(); }

std::string host_features() {
  llvm::SubtargetFeatures features;
  for (const auto& [name, enabled] : llvm::sys::getHostCPUFeatures()) features.AddFeature(name, enabled);
  return features.getString();
}

}  // namespace shadetree
