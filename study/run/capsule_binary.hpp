#pragma once
// Finding the `capsule` binary: $CAPSULE_BIN if set, else beside the study binary's
// build tree (build/study/study -> build/solver/capsule).
#include <filesystem>
#include <string>

namespace capsule::study {

// Throws std::runtime_error saying where it looked when no executable is there.
std::filesystem::path find_capsule_binary();

// The code version the capsule binary records in its member files (`capsule version`);
// throws std::runtime_error naming the binary when it cannot say.
std::string capsule_code_version(const std::filesystem::path& capsule);

// The running executable (/proc/self/exe).
std::filesystem::path own_executable();

}  // namespace capsule::study
