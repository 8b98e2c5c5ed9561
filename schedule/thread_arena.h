// The worker threads a command's --threads asks for (0: all the cores this
// process may run on), capped at the cores it may run on: oneTBB would
// ignore the rest anyway, with a warning on stderr (as under mpirun, which
// binds each rank to one core unless told otherwise).
#pragma once

#include <algorithm>

#include <tbb/info.h>
#include <tbb/task_arena.h>

namespace shadetree {

// How many worker threads --threads gives.
inline int worker_count(int threads) {
  return threads > 0 ? std::min(threads, tbb::info::default_concurrency()) : tbb::info::default_concurrency();
}

inline int arena_concurrency(int threads) {
  return threads > 0 ? std::min(threads, tbb::info::default_concurrency()) : tbb::task_arena::automatic;
}

}  // namespace shadetree
