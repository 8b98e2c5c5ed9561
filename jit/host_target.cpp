#include "jit/host_target.h"

#include <cpuid.h>

#include <cstring>
#include <string_view>

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

namespace {

// Whether the host's CPU is AMD's (its CPUID vendor string).
bool host_is_amd() {
  unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
  if (!__get_cpuid(0, &eax, &ebx, &ecx, &edx)) return false;
  char vendor[12];
  std::memcpy(vendor, &ebx, 4);
  std::memcpy(vendor + 4, &edx, 4);
  std::memcpy(vendor + 8, &ecx, 4);
  return std::string_view(vendor, 12) == "AuthenticAMD";
}

}  // namespace

// Measured with `shadetree bench --gathers` on both vendors (figures in
// docs/architecture.md, "Table lookups"): per-lane loads, which hash a
// noise cell's rows in general registers and read each knot's gradient
// from the interleaved table, beat every other strategy without AVX-512
// and on Zen 5, whose 512-bit units are whole; there the permutation's
// other lookups (cellular noise's hashes) are fastest as bytes in
// registers (VBMI). Zen 4 splits 512-bit operations and was measured
// (before rows were hashed in general registers) to prefer permutes over
// registers, the permutation as bytes cheapest; Intel's gathers beat the
// permute tree over sixteen registers of a float table, so there only the
// permutation is held in registers.
GatherStrategy host_gather_strategy() {
  if (host_vector_width() < 16) return GatherStrategy::per_lane;
  const bool vbmi = host_has("avx512vbmi");
  if (host_is_amd() && host_cpu_name() == "znver4")
    return vbmi ? GatherStrategy::in_register_byte_permutes : GatherStrategy::in_register;
  if (host_is_amd()) return vbmi ? GatherStrategy::byte_permutes_and_per_lane : GatherStrategy::per_lane;
  return vbmi ? GatherStrategy::byte_permutes_and_gathers : GatherStrategy::hardware;
}

std::string host_cpu_name() { return llvm::sys::getHostCPUName().str(); }

std::string host_features() {
  llvm::SubtargetFeatures features;
  for (const auto& [name, enabled] : llvm::sys::getHostCPUFeatures()) features.AddFeature(name, enabled);
  return features.getString();
}

}  // namespace shadetree
