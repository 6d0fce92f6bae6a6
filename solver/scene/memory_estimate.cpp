#include "solver/scene/memory_estimate.hpp"

#include <unistd.h>

#include <cstdio>

#include "solver/lbm/padded_rows.hpp"
#include "solver/scene/refined_block_extent.hpp"

namespace capsule {

MemoryEstimate estimate_memory(const Scene& s) {
  const auto g = s.grid();
  const double nx = g[0], ny = g[1], nz = s.dim == 3 ? g[2] : 1;
  const double n = nx * ny * nz;
  const double Q = s.dim == 3 ? 19 : 9;
  const lbm::PaddedRows rows(static_cast<std::size_t>(nx), static_cast<std::size_t>(ny * nz));
  MemoryEstimate m;
  // One padded array of populations (in-place streaming) at the scene's precision; force 3,
  // velocity 3, density 1 in double. Measured peak RSS of the reference 3D member (single,
  // 100 x 100 x 80, no restart point written): 133 MB against 131 MB from this and the base.
  const double population_bytes = s.resolution.precision == lbm::Precision::single_precision ? 4 : 8;
  m.fluid = Q * static_cast<double>(rows.per_population()) * population_bytes + 7 * n * 8;
  // The power law needs a viscosity field only in the text's fluid-shell reading (103)-(104).
  const bool shell = s.dim == 3 && s.power_law.K > 0 && s.power_law.model == PowerLawModel::fluid_shell;
  const bool field = s.V != 1.0 || shell;
  if (field) m.fields += 17 * n;                        // nu, s_nu, marked
  if (s.V != 1.0) m.fields += 19 * n;                   // distance, signed distance, band and inside flags, flood fill
  if (shell) m.fields += 16 * n + (s.V != 1.0 ? 8 * n : 0);  // field, slot (, base nu)
  if (s.dim == 3) {
    const double vertices = 10.0 * double(1L << (2 * s.resolution.mesh_level)) + 2;
    m.membrane = vertices * 1500;  // mesh, topology, forces, curvature fit, SLS memory (~1.5 kB per vertex)
  } else {
    m.membrane = s.resolution.segments * 400.0;
  }
  m.restart = (Q + 4 + (field ? 1 : 0)) * n * 8;
  if (s.resolution.refine) {
    // The refined fluid (solver/lbm/refinement/refined_fluid.hpp): two population arrays per
    // level at the scene's precision, the coarse force, velocity and density and the fine force
    // and velocity in double, and the stream tables (a destination slot for a tenth of the
    // cells, measured at a = 10-20). The restart point copies both levels' populations (as
    // doubles), density and velocities.
    const RefinedCellCounts c = refined_cell_counts(s);
    m.fluid = c.coarse * (2 * Q * population_bytes + 7 * 8) + c.fine * (2 * Q * population_bytes + 6 * 8) +
              0.1 * (c.coarse + c.fine) * Q * 8;
    m.restart = (c.coarse * (Q + 4) + c.fine * (Q + 3)) * 8;
  }
  m.base = 25e6;  // measured: 25 MB peak for a tiny scene
  return m;
}

double physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0.0;
}

std::string format_bytes(double b) {
  char text[32];
  if (b >= 1e9) std::snprintf(text, sizeof text, "%.2f GB", b / 1e9);
  else if (b >= 1e6) std::snprintf(text, sizeof text, "%.1f MB", b / 1e6);
  else std::snprintf(text, sizeof text, "%.0f kB", b / 1e3);
  return text;
}

std::string describe_memory(const MemoryEstimate& m) {
  return "memory: " + format_bytes(m.total()) + " (fluid " + format_bytes(m.fluid) + ", viscosity fields " +
         format_bytes(m.fields) + ", membrane " + format_bytes(m.membrane) + ", restart-point copy " +
         format_bytes(m.restart) + ")";
}

std::string memory_refusal(const Scene& scene) {
  const MemoryEstimate m = estimate_memory(scene);
  const double have = physical_memory_bytes();
  if (have <= 0 || m.total() <= have) return "";
  return "the scene needs about " + format_bytes(m.total()) + " of memory (" + describe_memory(m).substr(8) +
         "), more than this machine's " + format_bytes(have) + " of physical memory: lower resolution.a or resolution.domain";
}

}  // namespace capsule
