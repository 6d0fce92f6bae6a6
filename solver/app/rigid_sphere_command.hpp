#pragma once
#include <CLI/CLI.hpp>

#include "common/cli_support.hpp"

namespace capsule::cli {
// `capsule rigid-sphere ...`: adds the subcommand; its run() returns the exit status.
Command add_rigid_sphere_command(CLI::App& capsule);
// `capsule rigid-circle ...`: the 2D twin.
Command add_rigid_circle_command(CLI::App& capsule);
}  // namespace capsule::cli
