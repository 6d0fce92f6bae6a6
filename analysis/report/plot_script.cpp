#include "analysis/report/plot_script.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "plot_report_text.hpp"

namespace capsule::analysis {

namespace {
// Runs argv[0] with its arguments directly (no shell, so no path is ever interpreted),
// stdout and stderr to `log` (or /dev/null). Returns the exit status, -1 if it could not run.
int run(const std::vector<std::string>& args, const std::string& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
}  // namespace

const std::string& plot_script_text() {
  static const std::string text = k_plot_report_py;  // analysis/report/plot_report.py, embedded at build time
  return text;
}
std::string run_plot_script(const std::string& script_path, const std::string& data_path, const std::string& out_dir,
                            const std::string& python) {
  if (!std::filesystem::exists(python)) return "figures skipped: " + python + " not found";
  if (run({python, "-c", "import matplotlib"}, "/dev/null") != 0)
    return "figures skipped: " + python + " has no matplotlib";
  const std::string log = (std::filesystem::path(out_dir) / "plot_report.log").string();
  const int rc = run({python, script_path, data_path, out_dir}, log);
  if (rc != 0) return "figures skipped: the plotting script failed (exit " + std::to_string(rc) + "), see " + log;
  return "";
}

}  // namespace capsule::analysis
