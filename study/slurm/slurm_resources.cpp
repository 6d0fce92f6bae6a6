#include "study/slurm/slurm_resources.hpp"

#include <algorithm>
#include <cmath>
#include <regex>
#include <stdexcept>

#include "study/plan/cost_estimate.hpp"

namespace capsule::study {

namespace {

// Fluid rate assumed per thread, well under `capsule bench lbm` on the development machine
// (D2Q9 96-175, D3Q19 27 MLUPS per core) to leave room for the membrane (up to 14 % in
// 2D), a slower node and imperfect scaling; the time is then doubled and 10 minutes added.
constexpr double rate_2d = 20e6, rate_3d = 5e6;  // node updates per second per thread
// Bytes per lattice node: two population arrays of doubles (2 x 9 or 2 x 19) plus the
// macroscopic and force fields and, with V != 1, the viscosity field; then the program,
// membrane and HDF5 buffers; and half again as margin.
constexpr double bytes_2d = 300, bytes_3d = 600, base_megabytes = 200;

}  // namespace

long estimated_minutes(const Member& member, int cpus) {
  const CostEstimate c = estimate_cost(member.scene);
  const bool three_d = member.scene.at("dim").get<int>() == 3;
  const double seconds = c.node_steps() / ((three_d ? rate_3d : rate_2d) * std::max(1, cpus));
  return static_cast<long>(std::ceil(2.0 * seconds / 60.0)) + 10;
}

long estimated_megabytes(const Member& member) {
  const CostEstimate c = estimate_cost(member.scene);
  const bool three_d = member.scene.at("dim").get<int>() == 3;
  const double mb = 1.5 * (static_cast<double>(c.nodes) * (three_d ? bytes_3d : bytes_2d) / 1e6 + base_megabytes);
  return static_cast<long>(std::ceil(mb / 100.0)) * 100;  // whole hundreds of MB
}

bool is_slurm_time(const std::string& text) {
  // At most 8 digits before the first separator: 10^8 minutes (190 years) is past any queue.
  static const std::regex form(R"(^(\d{1,8}|\d{1,8}:\d{1,2}(:\d{1,2})?|\d{1,8}-\d{1,2}(:\d{1,2}(:\d{1,2})?)?)$)");
  return std::regex_match(text, form);
}

bool is_slurm_mem(const std::string& text) {
  static const std::regex form(R"(^\d{1,12}[KMGT]?$)");  // 10^12 of any unit is past any node
  return std::regex_match(text, form);
}

SlurmResources slurm_resources(const std::vector<const Member*>& pending, int threads, const std::string& time,
                               const std::string& mem) {
  if (!time.empty() && !is_slurm_time(time))
    throw std::invalid_argument("--time \"" + time + "\" is not a Slurm time (allowed: minutes, H:MM:SS, D-HH[:MM[:SS]], at most 8 digits a number)");
  if (!mem.empty() && !is_slurm_mem(mem))
    throw std::invalid_argument("--mem \"" + mem + "\" is not a Slurm memory size (allowed: megabytes, or a number with K, M, G or T, at most 12 digits)");
  SlurmResources r;
  bool any_3d = false;
  for (const Member* m : pending) any_3d = any_3d || m->scene.at("dim").get<int>() == 3;
  r.cpus = threads > 0 ? threads : (any_3d ? default_3d_cpus : 1);
  long minutes = 15, megabytes = 0;
  for (const Member* m : pending) {
    minutes = std::max(minutes, estimated_minutes(*m, r.cpus));
    megabytes = std::max(megabytes, estimated_megabytes(*m));
  }
  if (megabytes == 0) megabytes = 500;
  r.time = time.empty() ? std::to_string(minutes) : time;
  r.mem = mem.empty() ? std::to_string(megabytes) : mem;
  return r;
}

}  // namespace capsule::study
