#pragma once
#include <CLI/CLI.hpp>

#include "common/cli_support.hpp"

namespace capsule::cli {
// `capsule shapes MEMBER --at-kt T1,T2,...`: the shapes of a member that has ended at times its
// member file did not store, by rerunning its scene only as far as needed (solver/run/shape_rerun.hpp).
Command add_shapes_command(CLI::App& capsule);
}  // namespace capsule::cli
