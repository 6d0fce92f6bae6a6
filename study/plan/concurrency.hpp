#pragma once
// How many members run at once (GNU Parallel's -j) and how many OpenMP threads each gets.
namespace capsule::study {

struct Concurrency {
  int jobs = 1;
  int threads = 1;
};

// cores: usable cores; members: how many members will run; any_3d: whether one of them is 3D.
// requested_jobs / requested_threads: 0 = choose. Rules (a small 2D lattice gains more from
// running several members side by side than from splitting one over threads; a 3D lattice is
// large and memory-hungry, so one 3D member takes every core):
//   2D only: threads 1, jobs min(cores, members).
//   any 3D:  threads = cores, jobs 1.
//   one of the two given: the other is cores / given (at least 1); both given: as given.
Concurrency choose_concurrency(int cores, int members, bool any_3d, int requested_jobs, int requested_threads);

// std::thread::hardware_concurrency, honouring the CPU affinity mask (taskset, cgroups).
int usable_cores();

}  // namespace capsule::study
