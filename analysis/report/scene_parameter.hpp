#pragma once
// Looks up a numeric scene parameter (Ca, E_b, V, eta, ...) in a canonical scene: by
// the JSON pointer the analysis block gives for it, else, for a dotted name such as
// "resolution.a", at that path, else as the one key of that name anywhere in the scene.
#include <map>
#include <string>

#include <nlohmann/json.hpp>

namespace capsule::analysis {

struct SceneValue {
  bool found = false;
  double value = 0.0;
  std::string reason;  // why not found (absent, ambiguous, not a number)
  std::string pointer; // where it was found (a JSON pointer), also when it is not a number
};

SceneValue scene_parameter(const nlohmann::json& scene, const std::string& name,
                           const std::map<std::string, std::string>& pointers);

// The value at a dotted key ("resolution.a"), or nullptr when the scene has none.
const nlohmann::json* scene_value_at(const nlohmann::json& scene, const std::string& dotted_key);

// The keys a canonical scene (one with a dim and a resolution block) leaves out while they hold
// their default, with that default (Scene::omitted_defaults); nullptr for any other JSON.
const std::map<std::string, nlohmann::json>* omitted_scene_defaults(const nlohmann::json& scene);

// The scene with the value at a JSON pointer removed (for grouping members that agree in
// everything else); the scene itself when it has no such value.
nlohmann::json scene_without(const nlohmann::json& scene, const std::string& pointer);

}  // namespace capsule::analysis
