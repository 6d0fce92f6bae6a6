// capsule: runs one scene (one member of a study) and writes one member file.
// Thin command line over the solver library; all physics lives in solver/.
#include <CLI/CLI.hpp>
#include <iostream>
#include <nlohmann/json.hpp>

#include "solver/app/bench_command.hpp"
#include "solver/app/cli_support.hpp"
#include "solver/app/reference_bim_command.hpp"
#include "solver/app/rigid_sphere_command.hpp"
#include "solver/scene/memory_estimate.hpp"
#include "solver/run/run_member.hpp"
#include "solver/scene/scene.hpp"
#include "solver/scene/version.hpp"
#include "build_info.hpp"

namespace {
// docs/guide/scenes.md "Exit status"; run_member() and `check` return these.
const char* const exit_codes =
    "Exit status: 0 complete (check: the scene is valid), 1 the solver failed or a file could not be\n"
    "written, 2 bad scene, output path or command line (nothing was run), 3 the member ended unstable,\n"
    "4 stopped by SIGTERM, SIGINT or SIGUSR1 after writing a restart point (the same command continues).";

// `capsule check SCENE`: the canonical scene on stdout (study hashes it), the memory it needs on stderr.
int check_command(int argc, const char* const* argv) {
  CLI::App app{"capsule check: validate a scene and print it with every default filled in"};
  app.footer(exit_codes);
  std::string scene;
  app.add_option("scene", scene, "scene JSON file")->required();
  if (const int code = capsule::cli::parse_or_exit_code(app, argc, argv); code >= 0) return code;
  try {
    auto s = capsule::Scene::load(scene);
    if (const std::string refusal = capsule::memory_refusal(s); !refusal.empty()) {
      std::cerr << "capsule: " << scene << ": " << refusal << "\n";
      return 2;
    }
    std::cout << s.to_json().dump(2) << "\n";
    std::cerr << "capsule: " << capsule::describe_memory(capsule::estimate_memory(s)) << "; this machine has "
              << capsule::format_bytes(capsule::physical_memory_bytes()) << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "capsule: " << e.what() << "\n";
    return 2;
  }
}

// `capsule version`: what a member file of this binary records (study run checks it before each member).
int version_command(int argc, const char* const* argv) {
  CLI::App app{"capsule version: the code version and physics version this binary records in a member file, as JSON"};
  app.footer("Exit status: 0 printed, 2 bad command line.");
  if (const int code = capsule::cli::parse_or_exit_code(app, argc, argv); code >= 0) return code;
  std::cout << nlohmann::json{{"code_version", capsule::build::code_version},
                              {"physics_version", capsule::physics_version}}.dump() << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // `capsule SCENE -o OUT` is the common form; subcommands `check`, `bench` and
  // `reference-bim`, `rigid-sphere` and `rigid-circle` sit beside it.
  if (argc >= 2 && std::string(argv[1]) == "check") return check_command(argc - 1, argv + 1);
  if (argc >= 2 && std::string(argv[1]) == "version") return version_command(argc - 1, argv + 1);
  if (argc >= 2 && std::string(argv[1]) == "reference-bim") return capsule::cli::reference_bim_command(argc - 1, argv + 1);
  if (argc >= 2 && std::string(argv[1]) == "rigid-sphere") return capsule::cli::rigid_sphere_command(argc - 1, argv + 1);
  if (argc >= 2 && std::string(argv[1]) == "rigid-circle") return capsule::cli::rigid_circle_command(argc - 1, argv + 1);
  if (argc >= 2 && std::string(argv[1]) == "bench") return capsule::cli::bench_command(argc - 1, argv + 1);
  CLI::App app{"capsule: one capsule in shear flow (IB + MRT lattice Boltzmann + membrane FEM)\n"
               "  capsule SCENE.json -o MEMBER.h5   run one scene\n"
               "  capsule check SCENE.json          validate a scene\n"
               "  capsule version                   the code and physics version a member file records\n"
               "  capsule bench lbm                 fluid benchmark\n"
               "  capsule bench member3d            3D step benchmark, by part\n"
               "  capsule reference-bim --ca CA     boundary-integral reference capsule\n"
               "  capsule rigid-sphere --a A        rigid IB shell: torque and stresslet against Stokes\n"
               "  capsule rigid-circle --a A        rigid IB circle (2D): torque and stresslet against Stokes"};
  app.footer(exit_codes);
  capsule::RunOptions opt;
  app.add_option("scene", opt.scene_path, "scene JSON file")->required()->check(CLI::ExistingFile);
  app.add_option("-o,--output", opt.output_path, "member file to write (HDF5)")->required();
  app.add_option("--threads", opt.threads, "OpenMP threads inside this member (0 = OMP default)")
      ->check(capsule::cli::whole_number_at_least(0));
  app.add_option("--id", opt.member_id, "member id to record (set by study)");
  app.add_flag("-q,--quiet", opt.quiet, "no progress lines");
  app.add_option("--progress-seconds", opt.progress_seconds, "wall seconds between progress lines")
      ->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--checkpoint-seconds", opt.checkpoint.every_seconds,
                 "wall seconds between restart points (OUT.restart; 0 = none); rerunning the same command continues from the last one")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  // Hidden test options: a restart point at a given step, and an end as if killed.
  app.add_option("--checkpoint-at-step", opt.checkpoint.at_step)->group("")->check(CLI::NonNegativeNumber);
  app.add_option("--stop-after-step", opt.checkpoint.stop_after_step)->group("")->check(CLI::NonNegativeNumber);
  if (const int code = capsule::cli::parse_or_exit_code(app, argc, argv); code >= 0) return code;
  return capsule::run_member(opt);
}
