#pragma once
namespace capsule::cli {
// `capsule rigid-sphere ...` (argv[0] is the word rigid-sphere); returns the exit status.
int rigid_sphere_command(int argc, const char* const* argv);
// `capsule rigid-circle ...`: the 2D twin.
int rigid_circle_command(int argc, const char* const* argv);
}  // namespace capsule::cli
