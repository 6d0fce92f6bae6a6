#pragma once
namespace capsule::cli {
// `capsule bench lbm|member3d ...` (argv[0] is the word bench; solver/bench/); returns the exit status.
int bench_command(int argc, const char* const* argv);
}  // namespace capsule::cli
