#include "solver/run/checkpoint.hpp"

#include <signal.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <ostream>
#include <vector>

#include "build_info.hpp"
#include "solver/io/content_hash.hpp"
#include "common/json_text.hpp"
#include "solver/scene/version.hpp"

namespace capsule {

namespace {
// Bumped when the meaning of the saved names changes.
constexpr const char* kRestartFormat = "capsule restart point 1";
}  // namespace

double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

namespace {
volatile std::sig_atomic_t g_stop_signal = 0;
extern "C" void note_stop_signal(int signal) { g_stop_signal = signal; }
}  // namespace

void install_stop_signals() {
  struct sigaction action {};
  action.sa_handler = note_stop_signal;
  sigemptyset(&action.sa_mask);
  for (int signal : {SIGTERM, SIGINT, SIGUSR1}) sigaction(signal, &action, nullptr);
}

int stop_signal() { return g_stop_signal; }

std::string restart_path_for(const std::string& member_path) { return member_path + ".restart"; }

const std::string& binary_fingerprint() {
  static const std::string fingerprint = [] {
    std::ifstream in("/proc/self/exe", std::ios::binary);
    if (!in) return std::string("unknown");
    io::Fnv1a64 h;
    std::vector<char> buf(1 << 20);
    while (in.read(buf.data(), static_cast<std::streamsize>(buf.size())) || in.gcount() > 0) {
      const std::streamsize n = in.gcount();
      h.add(buf.data(), static_cast<std::size_t>(n));
      if (n < static_cast<std::streamsize>(buf.size())) break;
    }
    return h.hex();
  }();
  return fingerprint;
}

RestartIdentity current_identity(const std::string& canonical_scene, const std::string& member_id) {
  return {canonical_scene, physics_version, build::code_version, binary_fingerprint(), member_id};
}

void put_identity(io::StateArchive& a, const RestartIdentity& id) {
  a.put_text("identity.format", kRestartFormat);
  a.put_text("identity.scene", id.scene);
  a.put_text("identity.physics_version", id.physics_version);
  a.put_text("identity.code_version", id.code_version);
  a.put_text("identity.build", id.build);
  a.put_text("identity.member_id", id.member_id);
}

// The first key where two canonical scenes differ, as "key: saved -> now" (JSON pointer form
// turned dotted), or "the scene text" when either does not parse.
static std::string scene_difference(const std::string& saved, const std::string& now) {
  const nlohmann::json a = nlohmann::json::parse(saved, nullptr, false), b = nlohmann::json::parse(now, nullptr, false);
  if (a.is_discarded() || b.is_discarded()) return "the scene text differs";
  const nlohmann::json patch = nlohmann::json::diff(a, b);
  if (patch.empty()) return "the scene text differs";
  const nlohmann::json::json_pointer where(patch[0].at("path").get<std::string>());
  std::string key = where.to_string().substr(1);
  for (auto& c : key) c = c == '/' ? '.' : c;
  const std::string before = a.contains(where) ? message_value(a.at(where)) : "(absent)";
  const std::string after = b.contains(where) ? message_value(b.at(where)) : "(absent)";
  return "key " + message_text(key) + ": " + before + " in the restart point, " + after + " now";
}

std::string identity_mismatch(const io::StateArchive& a, const RestartIdentity& id) {
  const auto text = [&](const char* name) { return a.has(name) ? a.text(name) : std::string("(none)"); };
  if (text("identity.format") != kRestartFormat) return "another restart format (" + text("identity.format") + ")";
  if (text("identity.scene") != id.scene) return "another scene (" + scene_difference(text("identity.scene"), id.scene) + ")";
  if (text("identity.physics_version") != id.physics_version)
    return "physics version " + text("identity.physics_version") + ", this solver's is " + id.physics_version;
  if (text("identity.member_id") != id.member_id)
    return "member id \"" + text("identity.member_id") + "\", this run's is \"" + id.member_id + "\"";
  if (text("identity.code_version") != id.code_version || text("identity.build") != id.build)
    return "another build (code " + text("identity.code_version") + ", binary " + text("identity.build") +
           "; this one: code " + id.code_version + ", binary " + id.build + ")";
  return "";
}

std::unique_ptr<io::StateArchive> load_restart_point(const std::string& path, const RestartIdentity& id,
                                                     std::ostream& log) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return nullptr;
  std::string why;
  try {
    auto a = std::make_unique<io::StateArchive>(io::StateArchive::read(path));
    why = identity_mismatch(*a, id);
    if (why.empty()) return a;
  } catch (const std::exception& e) {
    why = e.what();
  }
  log << "capsule: restart point " << path << " refused: " << why << "; starting afresh\n";
  std::filesystem::remove(path, ec);
  return nullptr;
}

CheckpointClock::CheckpointClock(const CheckpointPolicy& policy) : policy_(policy), last_(steady_seconds()) {}

bool CheckpointClock::due(long step) const {
  if (policy_.at_step >= 0 && step == policy_.at_step) return true;
  return policy_.every_seconds > 0 && steady_seconds() - last_ >= policy_.every_seconds;
}

void CheckpointClock::written() { last_ = steady_seconds(); }

}  // namespace capsule
