#pragma once
// The memory a scene needs (docs/guide/running.md "Time and memory estimates"), counted from the arrays the
// solver allocates: the fluid's two population arrays (padded rows, Fluid<L>), its force,
// velocity and density fields, the per-node viscosity field and the contrast / power-law
// fields when the scene has them, the membrane, and the copy of the fluid a restart point
// makes while it is written. `capsule check` prints it and refuses a scene that needs more
// than the machine's physical memory; `capsule SCENE` refuses it before allocating.
#include <string>

#include "solver/scene/scene.hpp"

namespace capsule {

struct MemoryEstimate {
  double fluid = 0;     // populations, force, velocity, density
  double fields = 0;    // per-node viscosity, contrast, power law
  double membrane = 0;  // mesh or chain, forces, memories
  double restart = 0;   // the fluid's copy while a restart point is written
  double base = 0;      // the process itself (code, libraries, HDF5)
  double total() const { return fluid + fields + membrane + restart + base; }
};

MemoryEstimate estimate_memory(const Scene& scene);

double physical_memory_bytes();             // sysconf(_SC_PHYS_PAGES) * page size; 0 if unknown
std::string format_bytes(double bytes);     // "1.23 GB", "45.6 MB"
std::string describe_memory(const MemoryEstimate& m);  // "memory: 1.2 GB (fluid ..., ...)"
// "" when the scene fits this machine's physical memory, else the refusal with both numbers.
std::string memory_refusal(const Scene& scene);

}  // namespace capsule
