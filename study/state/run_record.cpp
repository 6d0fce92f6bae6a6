#include "study/state/run_record.hpp"

#include <fcntl.h>
#include <sys/file.h>

#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "build_info.hpp"
#include "solver/scene/version.hpp"
#include "study/state/results_layout.hpp"

namespace capsule::study {

std::string host_name() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

std::string utc_now_iso8601() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

nlohmann::json run_record_start(const std::string& campaign_name, const std::string& campaign_file) {
  return {{"campaign", campaign_name},
          {"campaign_file", std::filesystem::absolute(campaign_file).string()},
          {"code_version", capsule::build::code_version},
          {"physics_version", capsule::physics_version},
          {"host", host_name()},
          {"started", utc_now_iso8601()}};
}

void append_run_history(const std::filesystem::path& history, const nlohmann::json& record) {
  // Slurm tasks of one campaign append at the same time: one writer at a time (flock on a
  // lock file beside it; released when the descriptor closes), else one task's line is lost.
  const std::string lock_path = history.string() + ".lock";
  const int fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd >= 0) ::flock(fd, LOCK_EX);
  struct Unlock {
    int fd;
    ~Unlock() {
      if (fd >= 0) ::close(fd);
    }
  } unlock{fd};
  std::string text = read_file_text(history);
  if (!text.empty() && text.back() != '\n') text += '\n';
  write_file_atomically(history, text + record.dump() + "\n");
}

}  // namespace capsule::study
