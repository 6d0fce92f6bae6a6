#pragma once
// Paths that study writes into generated scripts and job lists (run_member.sh, the GNU
// Parallel job list, capsule.sbatch). Shell quoting makes every byte literal, but a line
// break still ends a job-list line or an #SBATCH line, and other control characters are
// never meant: such paths are refused before anything is written.
#include <filesystem>
#include <stdexcept>
#include <string>

namespace capsule::study {

// A path study refuses to put in a script; `study` exits 2 (a usage error).
struct UnsafePathError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Throws UnsafePathError "<what> contains a control character (byte 0x0a at 12): <path>".
void require_script_safe(const std::string& what, const std::filesystem::path& path);

}  // namespace capsule::study
