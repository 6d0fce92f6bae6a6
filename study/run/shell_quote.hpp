#pragma once
// POSIX shell single-quoting for the scripts study generates (wrapper, sbatch):
// every byte is taken literally, so no user string is ever interpreted by a shell.
#include <string>

namespace capsule::study {

// 'text' with each ' written as '\''.
std::string shell_quote(const std::string& text);

}  // namespace capsule::study
