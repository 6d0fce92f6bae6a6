#pragma once
// GNU Parallel's --joblog: one tab-separated row per finished job
// (Seq Host Starttime JobRuntime Send Receive Exitval Signal Command).
#include <filesystem>
#include <string>
#include <vector>

namespace capsule::study {

struct JoblogEntry {
  long seq = 0;
  std::string host;
  double start = 0;    // epoch seconds
  double runtime = 0;  // seconds
  int exit_value = 0;
  int signal = 0;
  std::string command;
};

// Missing file -> empty list. Rows that do not parse (a header line) are skipped. The
// file holds every run's rows (study run appends); filter on start to get one run's.
std::vector<JoblogEntry> read_joblog(const std::filesystem::path& path);

}  // namespace capsule::study
