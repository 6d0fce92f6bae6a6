#include "study/run/capsule_binary.hpp"

#include <cstdlib>
#include <stdexcept>
#include <unistd.h>

namespace capsule::study {

namespace fs = std::filesystem;

fs::path own_executable() { return fs::read_symlink("/proc/self/exe"); }

fs::path find_capsule_binary() {
  fs::path candidate;
  if (const char* env = std::getenv("CAPSULE_BIN"); env && *env) {
    candidate = fs::absolute(env);
  } else {
    candidate = own_executable().parent_path().parent_path() / "solver" / "capsule";
  }
  if (::access(candidate.c_str(), X_OK) != 0)
    throw std::runtime_error("no executable capsule binary at " + candidate.string() +
                             " (build the `capsule` target, or set CAPSULE_BIN)");
  return candidate;
}

}  // namespace capsule::study
