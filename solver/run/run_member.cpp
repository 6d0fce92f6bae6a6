// run_member(): one scene -> one member file (CONTRACTS.md "Member file", "Binaries").
#include "solver/run/run_member.hpp"

#include <omp.h>
#include <unistd.h>

#include <chrono>
#include <ctime>
#include <iostream>

#include "build_info.hpp"
#include "solver/io/member_file.hpp"
#include "solver/io/output_path.hpp"
#include "solver/run/simulation2d.hpp"
#include "solver/run/simulation3d.hpp"
#include "solver/scene/scene.hpp"
#include "solver/scene/version.hpp"

namespace capsule {
namespace {

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

std::string host_name() {
  char buf[256] = {};
  if (gethostname(buf, sizeof buf - 1) != 0) return "unknown";
  return buf;
}

}  // namespace

int run_member(const RunOptions& options) {
  if (const std::string problem = io::output_path_problem(options.output_path); !problem.empty()) {
    std::cerr << "capsule: " << problem << "\n";
    return 2;
  }
  Scene scene;
  try {
    scene = Scene::load(options.scene_path);
  } catch (const std::exception& e) {  // SceneError, or an unreadable file
    std::cerr << "capsule: " << e.what() << "\n";
    return 2;
  }
  if (options.threads > 0) omp_set_num_threads(options.threads);

  const auto t0 = std::chrono::steady_clock::now();
  try {
    io::MemberWriter out(options.output_path);
    out.set_scene(scene.to_json());
    out.set_attribute("member_id", options.member_id);
    out.set_attribute("code_version", build::code_version);
    out.set_attribute("physics_version", physics_version);
    out.set_attribute("host", host_name());
    out.set_attribute("started", utc_now());
    out.set_attribute("dim", static_cast<long>(scene.dim));
    out.set_attribute("threads", static_cast<long>(options.threads > 0 ? options.threads : omp_get_max_threads()));
    out.checkpoint();  // a .partial exists from the start

    std::string status;
    try {
      status = scene.dim == 2 ? run_simulation2d(scene, out, options.quiet)
                              : run_simulation3d(scene, out, options.quiet);
    } catch (const std::exception& e) {
      status = std::string("stopped: ") + e.what();
    }
    out.set_attribute("finished", utc_now());
    out.set_attribute("wall_seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    out.finish(status);
    if (!options.quiet || status != "complete") std::cerr << "capsule: " << options.output_path << ": " << status << "\n";
    if (status == "complete") return 0;
    if (status.rfind("unstable", 0) == 0) return 3;
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "capsule: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace capsule
