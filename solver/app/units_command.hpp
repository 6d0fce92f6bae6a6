#pragma once
#include <CLI/CLI.hpp>

#include "common/cli_support.hpp"

namespace capsule::cli {
// `capsule units SCENE`: the scene's dimensionless groups, from its physical block when it has
// one (with the formulas), and the lattice it runs on in micrometres and seconds.
Command add_units_command(CLI::App& capsule);
}  // namespace capsule::cli
