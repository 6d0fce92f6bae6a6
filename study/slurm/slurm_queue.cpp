#include "study/slurm/slurm_queue.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

namespace capsule::study {

namespace fs = std::filesystem;

namespace {

// Runs argv (no shell) and returns its standard output; exit < 0 when it could not be run.
std::string capture(const std::vector<std::string>& words, int& exit_status) {
  exit_status = -1;
  int pipe_fd[2];
  if (::pipe(pipe_fd) != 0) return "";
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(pipe_fd[0]);
    ::close(pipe_fd[1]);
    return "";
  }
  if (pid == 0) {
    ::dup2(pipe_fd[1], STDOUT_FILENO);
    ::close(pipe_fd[0]);
    ::close(pipe_fd[1]);
    std::vector<char*> argv;
    for (const auto& w : words) argv.push_back(const_cast<char*>(w.c_str()));
    argv.push_back(nullptr);
    ::execvp(argv[0], argv.data());
    ::_exit(127);
  }
  ::close(pipe_fd[1]);
  std::string out;
  char buf[4096];
  for (ssize_t n; (n = ::read(pipe_fd[0], buf, sizeof buf)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    out.append(buf, static_cast<std::size_t>(n));
  }
  ::close(pipe_fd[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return out;
}

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && ::access((fs::path(dir) / program).c_str(), X_OK) == 0) return true;
  return false;
}

}  // namespace

SlurmQueue slurm_queue(const ResultsLayout& layout) {
  SlurmQueue q;
  const fs::path record_file = layout.slurm_dir() / "export.json";
  std::error_code ec;
  if (!fs::exists(record_file, ec)) return q;
  const nlohmann::json record = nlohmann::json::parse(read_file_text(record_file), nullptr, false);
  if (!record.is_object() || !record.contains("scripts")) return q;
  if (!on_path("squeue")) return q;  // not on a Slurm machine: nothing queued here to ask about
  std::map<std::string, std::size_t> offsets;
  std::string names;
  for (const auto& sc : record["scripts"]) {
    offsets[sc.value("job_name", std::string())] = sc.value("offset", std::size_t{0});
    if (!names.empty()) names.append(",");
    names.append(sc.value("job_name", std::string()));
  }
  std::vector<std::string> lines;  // the job list: member folders
  {
    std::stringstream list(read_file_text(record.value("job_list", std::string())));
    for (std::string line; std::getline(list, line);) lines.push_back(line);
  }
  int status = 0;
  const std::string out =
      capture({"squeue", "--noheader", "--array", std::string("--name=").append(names), "--format=%j %K %T"}, status);
  if (status != 0) {
    q.note = std::string("squeue failed (exit status ").append(std::to_string(status)).append("): queued Slurm tasks are not known");
    return q;
  }
  std::stringstream rows(out);
  for (std::string name, task, state; rows >> name >> task >> state;) {
    if (state == "RUNNING" || state == "COMPLETING") continue;  // the member's lock tells those
    const auto it = offsets.find(name);
    if (it == offsets.end()) continue;
    std::size_t t = 0;
    try {
      t = std::stoul(task);
    } catch (const std::exception&) {
      continue;  // "N/A", a range not expanded
    }
    const std::size_t line = it->second + t;
    if (line >= lines.size()) continue;
    std::string where = "job ";
    where.append(name).append(" task ").append(task).append(" (").append(state).append(")");
    q.queued[fs::path(lines[line]).filename().string()] = where;
  }
  return q;
}

}  // namespace capsule::study
