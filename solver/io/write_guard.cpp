#include "solver/io/write_guard.hpp"

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace capsule::io {

namespace {

struct Guard {
  std::string lock_file, token;
};
Guard g_guard;

}  // namespace

void guard_writes_from_environment() {
  const char* file = std::getenv("CAPSULE_MEMBER_LOCK");
  const char* token = std::getenv("CAPSULE_MEMBER_LOCK_TOKEN");
  g_guard = {};
  if (file != nullptr && *file != '\0' && token != nullptr && *token != '\0') g_guard = {file, token};
}

void require_ownership(const std::string& what) {
  if (g_guard.lock_file.empty()) return;
  std::ifstream in(g_guard.lock_file);
  std::ostringstream text;
  text << in.rdbuf();
  const nlohmann::json j = nlohmann::json::parse(text.str(), nullptr, /*allow_exceptions=*/false);
  if (j.is_object() && j.value("token", std::string()) == g_guard.token) return;
  std::string owner = "no one (the lock is gone)";
  if (j.is_object()) owner = j.value("host", std::string("?")) + " (pid " + std::to_string(j.value("pid", 0L)) + ")";
  throw OwnershipLost{"the member's lock " + g_guard.lock_file + " now belongs to " + owner +
                      ": this run lost it (stopped longer than the lock's staleness?) and does not " + what};
}

}  // namespace capsule::io
