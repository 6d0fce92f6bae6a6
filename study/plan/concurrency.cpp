#include "study/plan/concurrency.hpp"

#include <algorithm>
#include <sched.h>
#include <thread>

namespace capsule::study {

Concurrency choose_concurrency(int cores, int members, bool any_3d, int requested_jobs, int requested_threads) {
  cores = std::max(1, cores);
  members = std::max(1, members);
  Concurrency c;
  if (requested_jobs > 0 && requested_threads > 0) {
    c.jobs = requested_jobs;
    c.threads = requested_threads;
  } else if (requested_jobs > 0) {
    c.jobs = requested_jobs;
    c.threads = any_3d ? std::max(1, cores / requested_jobs) : 1;
  } else if (requested_threads > 0) {
    c.threads = requested_threads;
    c.jobs = std::min(members, std::max(1, cores / requested_threads));
  } else if (any_3d) {
    c.jobs = 1;
    c.threads = cores;
  } else {
    c.threads = 1;
    c.jobs = std::min(cores, members);
  }
  return c;
}

int usable_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace capsule::study
