#pragma once
// Below this many nodes a lattice pass stays on one thread: a parallel region costs more
// than the work (tests, 2D toy runs).
#include <cstddef>

namespace capsule::lbm {
inline constexpr std::size_t parallel_threshold_nodes = 4096;
}  // namespace capsule::lbm
