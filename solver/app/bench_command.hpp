#pragma once
#include "common/cli_support.hpp"

namespace capsule::cli {
// `capsule bench lbm|member3d ...`: the fluid kernels' and a 3D member step's benchmarks
// (solver/bench/), added to capsule's command line.
Command add_bench_command(CLI::App& capsule);
}  // namespace capsule::cli
