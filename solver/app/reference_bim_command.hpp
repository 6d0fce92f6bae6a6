#pragma once
namespace capsule::cli {
// `capsule reference-bim ...` (argv[0] is the word reference-bim); returns the exit status.
int reference_bim_command(int argc, const char* const* argv);
}  // namespace capsule::cli
