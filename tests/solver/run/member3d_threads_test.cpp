// A 3D member is bitwise the same on 1 and 2 threads, and bitwise the same as before the
// membrane side of a step was parallelised (solver/ib/layer_spreading.hpp, the gathered
// Voronoi areas and triangle normals): no physics version changes with the thread count or
// with these speed-ups.
//
// Each member runs a few hundred lattice steps at a = 5 (50 x 50 x 40 nodes); the hash is
// FNV-1a over every series (name and bytes, in name order), the phase angles and the shapes.
// The recorded hashes were printed by the solver of commit e3d8b69 (before the speed-ups),
// on one thread and on two.
// Level 4 (2562 vertices) so that every threaded membrane loop runs threaded (the normals,
// Laplace-Beltrami weights and interpolation from 2048 vertices on).
#include <catch2/catch.hpp>
#include <omp.h>

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
const char* sphere_scene = R"({"dim": 3, "shape": "sphere", "Ca": 0.05, "E_b": 0.025, "V": 1, "eta": 0,
  "resolution": {"a": 5, "mesh_level": 4},
  "protocol": {"shear": {"until": "time", "kt": 0.2}, "recover": {"until": "time", "kt": 0}},
  "output": {"interval_kt": 0.02, "shapes_at_kt": [0.1, 0.2]}})";

// Everything else the membrane side of a step does: a biconcave start with spontaneous
// curvature, the viscosity contrast and the standard linear solid, the volume penalty, the
// cosine kernel, the Adams-Bashforth update, double precision; 300 steps (tau = 1).
const char* biconcave_scene = R"({"dim": 3, "shape": "biconcave", "Ca": 0.1, "E_b": 0.05, "V": 5, "eta": 5, "G": 1,
  "c0": -0.5, "volume_penalty": 1,
  "resolution": {"a": 5, "mesh_level": 4, "kernel": "cosine", "membrane_update": "adams_bashforth2", "precision": "double"},
  "protocol": {"shear": {"until": "time", "kt": 0.1}, "recover": {"until": "time", "kt": 0}},
  "output": {"interval_kt": 0.02, "shapes_at_kt": [0.1]}})";

// The power-law membrane viscosity (150 steps), which reads the normals and the Voronoi areas every step.
const char* power_law_scene = R"({"dim": 3, "shape": "sphere", "Ca": 0.05, "E_b": 0.025, "V": 1, "eta": 0,
  "power_law": {"K": 1, "n": 0.5},
  "resolution": {"a": 5, "mesh_level": 4},
  "protocol": {"shear": {"until": "time", "kt": 0.1}, "recover": {"until": "time", "kt": 0}},
  "output": {"interval_kt": 0.02, "shapes_at_kt": [0.1]}})";

}  // namespace

TEST_CASE("a 3D member is bitwise the same on 1 and 2 threads and as before the parallel membrane side",
          "[capsule3d][threads]") {
  struct Case {
    const char* name;
    const char* scene;
    const char* hash;  // recorded at commit e3d8b69
  };
  for (const Case& c : {Case{"sphere", sphere_scene, "735b580082927eab"}, Case{"biconcave", biconcave_scene, "7a29f6bf41284f56"},
                        Case{"power_law", power_law_scene, "be42a44160c879f9"}}) {
    for (int threads : {1, 2}) {
      INFO(c.name << " on " << threads << " threads");
      CHECK(member_hash(c.scene, c.name, threads) == c.hash);
    }
  }
}
