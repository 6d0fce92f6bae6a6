#pragma once
#include <CLI/CLI.hpp>

#include "common/cli_support.hpp"

namespace capsule::cli {
// `capsule reference-bim ...`: adds the subcommand; its run() returns the exit status.
Command add_reference_bim_command(CLI::App& capsule);
}  // namespace capsule::cli
