#include "study/state/process_alive.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <sstream>
#include <string>

namespace capsule::study {

bool process_alive(long pid) {
  if (pid <= 0) return false;
  if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno != EPERM) return false;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return true;  // no /proc: trust kill()
  const auto close = line.rfind(')');
  if (close == std::string::npos || close + 2 >= line.size()) return true;
  const char state = line[close + 2];
  return state != 'Z' && state != 'X';
}

long long process_start_ticks(long pid) {
  if (pid <= 0) return -1;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return -1;
  const auto close = line.rfind(')');  // the command name may hold spaces and parentheses
  if (close == std::string::npos) return -1;
  std::istringstream fields(line.substr(close + 2));
  std::string field;
  for (int i = 3; i <= 22 && fields >> field; ++i)  // fields 3 (state) to 22 (starttime)
    if (i == 22) return std::stoll(field);
  return -1;
}

double process_age_seconds(long pid) {
  const long long ticks = process_start_ticks(pid);
  std::ifstream uptime_file("/proc/uptime");
  double uptime = -1;
  if (ticks < 0 || !(uptime_file >> uptime)) return -1;
  const long hz = ::sysconf(_SC_CLK_TCK);
  return hz > 0 ? uptime - static_cast<double>(ticks) / static_cast<double>(hz) : -1;
}

}  // namespace capsule::study
