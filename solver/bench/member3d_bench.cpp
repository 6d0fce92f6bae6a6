// `capsule bench member3d`: where a step of a full 3D member goes (the step benchmark).
//
// The member is the default 3D scene of the reference member (sphere, neo-Hookean, Ca = 0.05,
// E_b = 0.025, V = 1, eta = 0, a = 10, level 4 = 2562 vertices, 100 x 100 x 80 nodes, the
// automatic tau), timed in both precisions with 1 and all threads, and once more with V = 5,
// where the viscosity field (15)-(16) is rebuilt every step. Parts (Simulation3D::step):
//   fluid      the fused stream-collide step (lbm::Fluid)
//   coupling   spreading (21), interpolation (19), the position update (20), clearing the force
//   (spread)   of which clearing the force and spreading (21)
//   viscosity  the viscosity field (V != 1 or a power-law membrane)
//   elastic    the membrane's elastic (and SLS) forces
//   curvature  the curvature fit of the bending force; bending: the bending force itself
// "membrane %" is (coupling + elastic + curvature + bending) / step: the goal is <= 15 %.
// Two more rows (and with --refine only these) run the same member on the refined fluid
// (resolution.refine, margin 0.6; docs/guide/refinement.md), per fine step (half a coarse
// step), with the fluid split into the coarse lattice, the fine sub-steps and the transfers.
// The same process runs every row, so their ratios survive a busy machine; the figures in
// docs/findings/performance.md "The reference 3D member" were taken on an idle one.
#include "solver/bench/member3d_bench.hpp"

#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "solver/run/simulation3d.hpp"
#include "solver/scene/scene.hpp"

namespace capsule {

namespace {

Scene bench_scene(const std::string& precision, double V, int a, int mesh_level, bool refine) {
  nlohmann::json j = {{"dim", 3},
                      {"shape", "sphere"},
                      {"Ca", 0.05},
                      {"E_b", 0.025},
                      {"V", V},
                      {"eta", 0},
                      {"resolution", {{"a", a}, {"mesh_level", mesh_level}, {"precision", precision}}},
                      {"protocol", {{"shear", {{"until", "time"}, {"kt", 1}}}, {"recover", {{"until", "time"}, {"kt", 0}}}}}};
  if (refine) j["resolution"]["refine"] = {{"margin", 0.6}};
  return Scene::from_json(j, "capsule bench member3d");
}

}  // namespace

int bench_member3d(bool quick, int max_threads, int a, int mesh_level, bool refined_only) {
  try {
    const int all = max_threads > 0 ? max_threads : omp_get_num_procs();
    std::vector<int> thread_counts{1};
    if (all > 1) thread_counts.push_back(all);
    const long warmup = quick ? 5 : 20, steps = quick ? 30 : 200;
    std::printf("capsule bench member3d: sphere Ca 0.05, E_b 0.025, a = %d, level %d; %ld steps after %ld\n", a, mesh_level,
                steps, warmup);
    std::printf("%-9s %5s %7s %9s %8s %8s %8s %9s %8s %9s %8s %9s %9s\n", "precision", "V", "threads", "ms/step", "fluid",
                "coupling", "(spread)", "viscosity", "elastic", "curvature", "bending", "membrane%", "fluidMLUPS");
    struct Row {
      std::string precision;
      double V;
      int threads;
      bool refine;
    };
    std::vector<Row> rows;
    if (!refined_only) {
      for (const char* p : {"double", "single"})
        for (int t : thread_counts) rows.push_back({p, 1.0, t, false});
      rows.push_back({"double", 5.0, all, false});
    }
    for (const char* p : {"double", "single"})
      for (int t : thread_counts) rows.push_back({p, 1.0, t, true});
    for (const auto& row : rows) {
      omp_set_num_threads(row.threads);
      const Scene scene = bench_scene(row.precision, row.V, a, mesh_level, row.refine);
      // A refined step is a coarse step: half as many of them, each counted as two fine steps.
      StepSplit3D s = time_steps3d(scene, row.refine ? (warmup + 1) / 2 : warmup, row.refine ? (steps + 1) / 2 : steps);
      if (s.refined)
        for (double* part : {&s.total, &s.fluid, &s.coupling, &s.spreading, &s.viscosity, &s.elastic, &s.curvature, &s.bending,
                             &s.coarse, &s.fine, &s.transfers, &s.nodes})
          *part *= 0.5;
      const double membrane = s.coupling + s.elastic + s.curvature + s.bending;
      std::printf("%-9s %5.1f %7d %9.3f %8.3f %8.3f %8.3f %9.3f %8.3f %9.3f %8.3f %8.1f%% %9.1f\n", row.precision.c_str(), row.V,
                  row.threads, 1e3 * s.total, 1e3 * s.fluid, 1e3 * s.coupling, 1e3 * s.spreading, 1e3 * s.viscosity, 1e3 * s.elastic,
                  1e3 * s.curvature, 1e3 * s.bending, s.total > 0 ? 100.0 * membrane / s.total : 0.0,
                  s.fluid > 0 ? s.nodes / s.fluid / 1e6 : 0.0);
      if (s.refined)
        std::printf("  refined (margin 0.6), per fine step: coarse lattice %.3f ms, fine lattice %.3f ms, transfers %.3f ms; "
                    "%.0f node updates (half the coarse cells and the fine ones)\n",
                    1e3 * s.coarse, 1e3 * s.fine, 1e3 * s.transfers, s.nodes);
      std::fflush(stdout);
    }
    std::printf("(ms per lattice step; parts need not add up to the step: the rest is the step's bookkeeping)\n");
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "capsule bench member3d: %s\n", e.what());
    return 1;
  }
}

}  // namespace capsule
