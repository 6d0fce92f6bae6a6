#pragma once
// Looks up a numeric scene parameter (Ca, E_b, V, eta, ...) in a canonical scene: by
// the JSON pointer the analysis block gives for it, else as the one key of that name
// anywhere in the scene.
#include <map>
#include <string>

#include <nlohmann/json.hpp>

namespace capsule::analysis {

struct SceneValue {
  bool found = false;
  double value = 0.0;
  std::string reason;  // why not found (absent, ambiguous, not a number)
};

SceneValue scene_parameter(const nlohmann::json& scene, const std::string& name,
                           const std::map<std::string, std::string>& pointers);

}  // namespace capsule::analysis
