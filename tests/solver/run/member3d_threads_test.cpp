// A 3D member is bitwise the same on 1 and 2 threads, and bitwise the same as before the
// membrane side of a step was parallelised (solver/ib/layer_spreading.hpp, the gathered
// Voronoi areas and triangle normals): no physics version changes with the thread count or
// with these speed-ups.
//
// Each member runs a few hundred lattice steps at a = 5 (50 x 50 x 40 nodes); the hash is
// FNV-1a over every series (name and bytes, in name order), the phase angles and the shapes.
// The recorded hashes were printed by the solver of commit e3d8b69 (before the speed-ups; the
// scenes name physics version 5, whose defaults that solver ran), on one thread and on two, on a machine whose libm fingerprint is recorded beside them; where the
// C library rounds otherwise, only 1 against 2 threads is checked.
// Level 4 (2562 vertices) so that every threaded membrane loop runs threaded (the normals,
// Laplace-Beltrami weights and interpolation from 2048 vertices on).
#include <catch2/catch.hpp>
#include <omp.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "solver/io/content_hash.hpp"
#include "solver/io/member_file.hpp"
#include "solver/run/simulation3d.hpp"
#include "solver/scene/scene.hpp"

using namespace capsule;

namespace {

std::string member_hash(const std::string& scene_json, const std::string& name, int threads) {
  omp_set_num_threads(threads);
  const Scene scene = Scene::from_json(nlohmann::json::parse(scene_json), name);
  const std::string path =
      (std::filesystem::temp_directory_path() / ("member3d_threads_test_" + name + std::to_string(threads) + ".h5")).string();
  std::string status;
  {
    io::MemberWriter out(path);
    status = run_simulation3d(scene, out, true);
    out.finish(status);
  }
  const io::MemberData d = io::read_member(path);
  std::filesystem::remove(path);
  omp_set_num_threads(1);
  REQUIRE(d.status == "complete");
  io::Fnv1a64 h;
  for (const auto& [series, values] : d.series) {
    h.add(series);
    h.add(values.data(), values.size() * sizeof(double));
  }
  for (const auto& row : d.beta) h.add(row.data(), row.size() * sizeof(double));
  for (const auto& s : d.shapes) h.add(s.xyz.data(), s.xyz.size() * sizeof(double));
  return h.hex();
}

// The reference member's physics (Ca 0.05, E_b 0.025, single precision), 300 steps.
const char* sphere_scene = R"({"dim": 3, "physics_version": "5", "shape": "sphere", "Ca": 0.05, "E_b": 0.025, "V": 1, "eta": 0,
  "resolution": {"a": 5, "mesh_level": 4},
  "protocol": {"shear": {"until": "time", "kt": 0.2}, "recover": {"until": "time", "kt": 0}},
  "output": {"interval_kt": 0.02, "shapes_at_kt": [0.1, 0.2]}})";

// Everything else the membrane side of a step does: a biconcave start with spontaneous
// curvature, the viscosity contrast and the standard linear solid, the volume penalty, the
// cosine kernel, the Adams-Bashforth update, double precision; 300 steps (tau = 1).
const char* biconcave_scene = R"({"dim": 3, "physics_version": "5", "shape": "biconcave", "Ca": 0.1, "E_b": 0.05, "V": 5, "eta": 5, "G": 1,
  "c0": -0.5, "volume_penalty": 1,
  "resolution": {"a": 5, "mesh_level": 4, "kernel": "cosine", "membrane_update": "adams_bashforth2", "precision": "double"},
  "protocol": {"shear": {"until": "time", "kt": 0.1}, "recover": {"until": "time", "kt": 0}},
  "output": {"interval_kt": 0.02, "shapes_at_kt": [0.1]}})";

// The power-law membrane viscosity (150 steps), which reads the normals and the Voronoi areas every step.
const char* power_law_scene = R"({"dim": 3, "physics_version": "5", "shape": "sphere", "Ca": 0.05, "E_b": 0.025, "V": 1, "eta": 0,
  "power_law": {"K": 1, "n": 0.5},
  "resolution": {"a": 5, "mesh_level": 4},
  "protocol": {"shear": {"until": "time", "kt": 0.1}, "recover": {"until": "time", "kt": 0}},
  "output": {"interval_kt": 0.02, "shapes_at_kt": [0.1]}})";

// The bits of the C library's transcendental functions the members use (the shapes, the phase
// angles, the power law). The recorded hashes hold only where these are the recording machine's:
// glibc picks its implementations by CPU at run time, and another libm may round differently.
std::string libm_fingerprint() {
  io::Fnv1a64 h;
  for (int i = 1; i <= 64; ++i) {
    const double x = 0.37 * i - 11.3, y = 0.011 * i + 0.05;
    const double v[] = {std::sin(x), std::cos(x), std::atan2(x, 1.7), std::pow(y, 0.64), std::exp(0.1 * x),
                        std::log(y), std::acos(std::tanh(0.2 * x)), std::cbrt(y)};
    h.add(v, sizeof(v));
  }
  return h.hex();
}

}  // namespace

TEST_CASE("a 3D member is bitwise the same on 1 and 2 threads and as before the parallel membrane side",
          "[capsule3d][threads]") {
  struct Case {
    const char* name;
    const char* scene;
    const char* hash;  // recorded at commit e3d8b69
  };
  const std::string libm = libm_fingerprint(), recorded_libm = "d2ab16d2f19472db";
  const bool recording_libm = libm == recorded_libm;
  if (!recording_libm)
    WARN("this C library's transcendental functions round otherwise than the recording machine's (fingerprint "
         << libm << ", recorded " << recorded_libm << "): 1 against 2 threads is checked, the recorded hashes are not");
  for (const Case& c : {Case{"sphere", sphere_scene, "735b580082927eab"}, Case{"biconcave", biconcave_scene, "7a29f6bf41284f56"},
                        Case{"power_law", power_law_scene, "be42a44160c879f9"}}) {
    const std::string one = member_hash(c.scene, c.name, 1), two = member_hash(c.scene, c.name, 2);
    INFO(c.name);
    CHECK(one == two);
    if (recording_libm) CHECK(one == c.hash);
  }
}

TEST_CASE("a 3D member of today's physics (roma3 with its inset, trt, the membrane power law) is bitwise the same on 1 and 2 threads",
          "[capsule3d][threads]") {
  for (const auto& [name, scene] : {std::pair{"sphere6", sphere_scene}, std::pair{"biconcave6", biconcave_scene},
                                    std::pair{"power_law6", power_law_scene}}) {
    nlohmann::json j = nlohmann::json::parse(scene);
    j.erase("physics_version");
    const std::string one = member_hash(j.dump(), name, 1), two = member_hash(j.dump(), name, 2);
    INFO(name);
    CHECK(one == two);
  }
}
