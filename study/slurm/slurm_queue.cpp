#include "study/slurm/slurm_queue.hpp"

#include "study/run/captured_command.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

namespace capsule::study {

namespace fs = std::filesystem;

namespace {

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && ::access((fs::path(dir) / program).c_str(), X_OK) == 0) return true;
  return false;
}

}  // namespace

QueuedMembers slurm_queue(const ResultsLayout& layout) {
  QueuedMembers q;
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
      captured_output({"squeue", "--noheader", "--array", std::string("--name=").append(names), "--format=%j %K %T"}, status);
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
