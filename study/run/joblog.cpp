#include "study/run/joblog.hpp"

#include <fstream>
#include <sstream>

namespace capsule::study {

std::vector<JoblogEntry> read_joblog(const std::filesystem::path& path) {
  std::vector<JoblogEntry> entries;
  std::ifstream in(path);
  std::string line;
  // No header line to skip: with --joblog +FILE (appending, as `study run` does) GNU Parallel
  // writes none when it creates the file, so the first line may be a row. A header ("Seq
  // Host ...") does not parse as a row and is skipped below like any other.
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream ss(line);
    std::string field;
    while (fields.size() < 8 && std::getline(ss, field, '\t')) fields.push_back(field);
    std::getline(ss, field);  // the command may itself contain tabs
    if (fields.size() < 8) continue;
    try {
      JoblogEntry e;
      e.seq = std::stol(fields[0]);
      e.host = fields[1];
      e.start = std::stod(fields[2]);
      e.runtime = std::stod(fields[3]);
      e.exit_value = std::stoi(fields[6]);
      e.signal = std::stoi(fields[7]);
      e.command = field;
      entries.push_back(std::move(e));
    } catch (const std::exception&) {
      continue;
    }
  }
  return entries;
}

}  // namespace capsule::study
