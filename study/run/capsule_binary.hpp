#pragma once
// Finding the `capsule` binary: $CAPSULE_BIN if set, else beside the study binary's
// build tree (build/study/study -> build/solver/capsule).
#include <filesystem>

namespace capsule::study {

// Throws std::runtime_error saying where it looked when no executable is there.
std::filesystem::path find_capsule_binary();

// The running executable (/proc/self/exe).
std::filesystem::path own_executable();

}  // namespace capsule::study
