// `capsule bench`: the fluid kernels' and a 3D member step's benchmarks (solver/bench/).
#include "solver/app/bench_command.hpp"

#include <CLI/CLI.hpp>
#include <iostream>
#include <string>

#include "solver/app/cli_support.hpp"
#include "solver/bench/lbm_bench.hpp"
#include "solver/bench/member3d_bench.hpp"

namespace capsule::cli {

int bench_command(int argc, const char* const* argv) {
  CLI::App app{"capsule bench: performance benchmarks"};
  app.footer("Exit status: 0 done, 1 failure, 2 bad command line.");
  std::string what;
  bool quick = false;
  int threads = 0;
  app.add_option("what", what, "what to benchmark: lbm (the fluid kernels), member3d (a step of the default 3D member, by part)")
      ->required()
      ->check(CLI::IsMember({"lbm", "member3d"}));
  app.add_flag("--quick", quick, "fewer steps per measurement");
  app.add_option("--threads", threads, "largest thread count to try (0 = all cores)")
      ->check(whole_number_at_least(0));
  int a = 10, mesh_level = 4;
  app.add_option("--a", a, "member3d: capsule radius in lattice nodes")->capture_default_str()->check(CLI::Range(3, 40));
  app.add_option("--mesh-level", mesh_level, "member3d: icosphere level of the membrane")
      ->capture_default_str()
      ->check(CLI::Range(0, 6));
  if (const int code = capsule::cli::parse_or_exit_code(app, argc, argv); code >= 0) return code;
  if (what != "member3d" && (app.count("--a") > 0 || app.count("--mesh-level") > 0)) {
    std::cerr << "capsule bench: --a and --mesh-level apply to member3d only\n";
    return 2;
  }
  return what == "member3d" ? capsule::bench_member3d(quick, threads, a, mesh_level) : capsule::lbm::bench_lbm(quick, threads);
}

}  // namespace capsule::cli
