#include "study/run/capsule_binary.hpp"

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <unistd.h>

#include "study/run/captured_command.hpp"

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

std::string capsule_code_version(const fs::path& capsule) {
  int status = -1;
  const std::string text = captured_output({capsule.string(), "version"}, status);
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (status != 0 || !j.is_object() || !j.contains("code_version") || !j["code_version"].is_string())
    throw std::runtime_error("the capsule binary " + capsule.string() + " does not say its code version (`" +
                             capsule.string() + " version` exited " + std::to_string(status) +
                             "): rebuild it with this study binary");
  return j["code_version"].get<std::string>();
}

}  // namespace capsule::study
