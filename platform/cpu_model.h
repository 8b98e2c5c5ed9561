// The processor a measurement ran on, named as the operating system names
// it, so that benchmark figures say what they were measured on (lookup
// strategies rank differently on Intel and AMD).
#pragma once

#include <string>

namespace shadetree {

// The model name /proc/cpuinfo gives ("AMD EPYC ...", "Intel(R) Xeon(R)
// ..."), or "an unnamed CPU" where it gives none.
std::string cpu_model_name();

}  // namespace shadetree
