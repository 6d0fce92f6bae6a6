#include "study/run/run_lock.hpp"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <sys/file.h>
#include <unistd.h>

#include "study/run/lock_holders.hpp"
#include "study/state/process_alive.hpp"
#include "study/state/results_layout.hpp"
#include "study/state/run_record.hpp"

namespace capsule::study {

namespace fs = std::filesystem;

namespace {

std::string pid_state(long pid) {
  if (pid <= 0) return "not started";
  if (process_alive(pid)) return "running";  // a killed one left a zombie where PID 1 does not reap
  return "no longer running";
}

}  // namespace

std::string describe_running(const fs::path& info_file, const std::vector<std::string>& running_members) {
  std::ostringstream m;
  m << "another `study run` of this campaign is still going";
  const nlohmann::json info = nlohmann::json::parse(read_file_text(info_file), nullptr, /*allow_exceptions=*/false);
  if (info.is_object()) {
    const long study_pid = info.value("study_pid", 0L), parallel_pid = info.value("parallel_pid", 0L);
    m << " (started " << info.value("started", std::string("?")) << " on " << info.value("host", std::string("?"))
      << "): study pid " << study_pid << " (" << pid_state(study_pid) << "), GNU Parallel pid " << parallel_pid << " ("
      << pid_state(parallel_pid) << ")";
  } else {
    m << " (no record of its processes in " << info_file.string() << ")";
  }
  m << "; " << running_members.size() << " member" << (running_members.size() == 1 ? "" : "s") << " running";
  for (std::size_t i = 0; i < running_members.size() && i < 10; ++i) m << (i == 0 ? ": " : ", ") << running_members[i];
  if (running_members.size() > 10) m << ", ...";
  m << ". Wait for it to end (`study status` shows progress) or stop it (kill the GNU Parallel pid twice)";
  return m.str();
}

RunLock::RunLock(const fs::path& lock_file, const fs::path& info_file, const std::vector<std::string>& running_members)
    : info_file_(info_file), started_(utc_now_iso8601()) {
  fd_ = ::open(lock_file.c_str(), O_RDWR | O_CREAT, 0644);
  if (fd_ < 0) throw std::runtime_error("cannot open " + lock_file.string() + ": " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    fd_ = -1;
    throw RunStillGoing(describe_running(info_file, running_members) + " (" + lock_file.string() + " is locked" +
                        describe_lock_holders(lock_file) + ")");
  }
  record(0);
}

RunLock::~RunLock() {
  if (fd_ >= 0) ::close(fd_);
}

void RunLock::record(long parallel_pid) const {
  const nlohmann::json info = {{"study_pid", static_cast<long>(::getpid())},
                               {"parallel_pid", parallel_pid},
                               {"host", host_name()},
                               {"started", started_}};
  write_file_atomically(info_file_, info.dump() + "\n");
}

}  // namespace capsule::study
