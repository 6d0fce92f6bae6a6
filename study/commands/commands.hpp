#pragma once
// The subcommands of `study` (docs/guide/campaigns.md "Commands"), one file each: every
// add_*_command() adds its subcommand, with its options, to the app; the returned run() calls
// the library and returns the exit status (study/state/exit_status.hpp).
#include <CLI/CLI.hpp>

#include "common/cli_support.hpp"

namespace capsule::study {

// `study plan CAMPAIGN...`: the members, their state and cost; changes nothing.
cli::Command add_plan_command(CLI::App& study);
// `study run CAMPAIGN...`: every member that is not complete, with GNU Parallel; resumable.
cli::Command add_run_command(CLI::App& study);
// `study run-member MEMBER_DIR THREADS`: one member, as every engine runs it.
cli::Command add_run_member_command(CLI::App& study);
// `study status CAMPAIGN`: counts per state and the reasons of members that are not complete.
cli::Command add_status_command(CLI::App& study);
// `study report CAMPAIGN`: fits, tables and figures in results/<campaign>/report.
cli::Command add_report_command(CLI::App& study);
// `study compare CAMPAIGN...`: the fits of several campaigns' reports side by side.
cli::Command add_compare_command(CLI::App& study);
// `study thesis` (alias `dissertation`): THESIS.md, the shipped results against the dissertation.
cli::Command add_thesis_command(CLI::App& study);
// `study export CAMPAIGN... --slurm`: a job list and Slurm array scripts.
cli::Command add_export_command(CLI::App& study);

}  // namespace capsule::study
