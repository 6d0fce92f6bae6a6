#pragma once
// What one Slurm array task asks for: CPUs, wall time and memory. Not the exporting
// machine's core count (the cluster's nodes differ): --threads on the command line, else
// 1 for 2D members and default_3d_cpus for 3D. Time and memory come from the cost
// estimate (cost_estimate.hpp) of the largest pending member, with generous margins,
// and can be given instead (--time, --mem).
#include <string>
#include <vector>

#include "study/campaign/expansion.hpp"

namespace capsule::study {

inline constexpr int default_3d_cpus = 8;

struct SlurmResources {
  int cpus = 1;
  std::string time;  // Slurm --time: minutes, or [D-]HH:MM[:SS]
  std::string mem;   // Slurm --mem: megabytes, or a number with K, M, G or T
};

// threads 0: chosen as above. time / mem "": estimated. Throws std::invalid_argument
// when a given time or mem is not in Slurm's form.
SlurmResources slurm_resources(const std::vector<const Member*>& pending, int threads, const std::string& time,
                               const std::string& mem);

// The estimates alone, for one member on `cpus` threads.
long estimated_minutes(const Member& member, int cpus);
long estimated_megabytes(const Member& member);

// True for Slurm's --time forms ("90", "1:30:00", "2-12", "2-12:00:00") and --mem forms ("4096", "4G").
bool is_slurm_time(const std::string& text);
bool is_slurm_mem(const std::string& text);

}  // namespace capsule::study
