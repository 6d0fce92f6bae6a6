#include "study/joblog.hpp"

#include <fstream>
#include <sstream>

namespace capsule::study {

std::vector<JoblogEntry> read_joblog(const std::filesystem::path& path) {
  std::vector<JoblogEntry> entries;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
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
