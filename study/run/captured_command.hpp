#pragma once
// Running a program without a shell and reading what it prints.
#include <string>
#include <vector>

namespace capsule::study {

// Runs words[0] (searched on PATH) with the rest as its arguments, no shell, and returns its
// standard output; exit_status is its exit status, 128 + the signal, or -1 when it could not be
// started at all (127 when exec failed).
std::string captured_output(const std::vector<std::string>& words, int& exit_status);

}  // namespace capsule::study
