// `capsule bench`: the fluid kernels' and a 3D member step's benchmarks (solver/bench/).
#include "solver/app/bench_command.hpp"

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <string>

#include "solver/bench/lbm_bench.hpp"
#include "solver/bench/member3d_bench.hpp"

namespace capsule::cli {

Command add_bench_command(CLI::App& capsule) {
  struct Settings {
    std::string what;
    bool quick = false, refine = false;
    int threads = 0, a = 10, mesh_level = 4;
  };
  auto s = std::make_shared<Settings>();
  CLI::App& app = *capsule.add_subcommand("bench", "performance benchmarks: lbm (the fluid), member3d (a 3D step, by part)");
  app.footer("Example: capsule bench member3d --quick --a 7 --mesh-level 3\n"
             "Exit status: 0 done, 1 failure, 2 bad command line.");
  app.add_option("what", s->what, "what to benchmark: lbm (the fluid kernels), member3d (a step of the default 3D member, by part)")
      ->required()
      ->check(CLI::IsMember({"lbm", "member3d"}));
  app.add_flag("--quick", s->quick, "fewer steps per measurement");
  app.add_option("--threads", s->threads, "largest thread count to try (0 = all cores)")->check(whole_number_at_least(0));
  app.add_option("--a", s->a, "member3d: capsule radius in lattice nodes")->capture_default_str()->check(CLI::Range(3, 40));
  app.add_option("--mesh-level", s->mesh_level, "member3d: icosphere level of the membrane")
      ->capture_default_str()
      ->check(CLI::Range(0, 6));
  app.add_flag("--refine", s->refine, "member3d: only the rows on the refined fluid (resolution.refine, margin 0.6)");
  return {&app, [s, &app] {
            if (s->what != "member3d" && (app.count("--a") > 0 || app.count("--mesh-level") > 0 || s->refine)) {
              std::cerr << "capsule bench: --a, --mesh-level and --refine apply to member3d only\n";
              return 2;
            }
            return s->what == "member3d" ? capsule::bench_member3d(s->quick, s->threads, s->a, s->mesh_level, s->refine)
                                         : capsule::lbm::bench_lbm(s->quick, s->threads);
          }};
}

}  // namespace capsule::cli
