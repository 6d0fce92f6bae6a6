#pragma once
// The smallest members the run tests use (restart, shapes rerun): every part of the state a
// restart point or a rerun must reproduce, in about a second.
#include <nlohmann/json.hpp>
#include <vector>

namespace capsule::testing {

// 2D, a = 4, 32 segments: viscosity contrast, implicit membrane viscosity, bending and a shear
// phase ended by a condition, in ~0.3 s.
inline nlohmann::json tiny_2d_scene(double Ca, const std::vector<double>& shapes_at_kt) {
  nlohmann::json output = {{"interval_kt", 0.05}};
  if (!shapes_at_kt.empty()) output["shapes_at_kt"] = shapes_at_kt;
  return {{"dim", 2}, {"shape", "circle"}, {"Ca", Ca}, {"E_b", 0.05}, {"V", 2}, {"eta", 3},
          {"resolution", {{"a", 4}, {"segments", 32}}},
          {"protocol", {{"shear", {{"until", "steady"}, {"window_kt", 0.3}, {"tolerance", 0.01}, {"max_kt", 1.0}}},
                        {"recover", {{"until", "time"}, {"kt", 0.4}}}}},
          {"output", output}};
}

// 3D, a = 4, level 2, a 20 x 20 x 16 box: 384 steps at the automatic tau = 1.5, about a second
// on one core.
inline nlohmann::json tiny_3d_scene(const std::vector<double>& shapes_at_kt) {
  nlohmann::json output = {{"interval_kt", 0.05}};
  if (!shapes_at_kt.empty()) output["shapes_at_kt"] = shapes_at_kt;
  return {{"dim", 3}, {"shape", "sphere"}, {"Ca", 0.1}, {"E_b", 0.05}, {"V", 1}, {"eta", 0},
          {"resolution", {{"a", 4}, {"mesh_level", 2}, {"domain", {5, 5, 4}}}},
          {"protocol", {{"shear", {{"until", "time"}, {"kt", 0.3}}}, {"recover", {{"until", "time"}, {"kt", 0.1}}}}},
          {"output", output}};
}

}  // namespace capsule::testing
