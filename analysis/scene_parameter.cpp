#include "analysis/scene_parameter.hpp"

#include <vector>

namespace capsule::analysis {

namespace {
void collect(const nlohmann::json& j, const std::string& name, std::vector<const nlohmann::json*>& hits) {
  if (j.is_object()) {
    for (const auto& [key, value] : j.items()) {
      if (key == name) hits.push_back(&value);
      collect(value, name, hits);
    }
  } else if (j.is_array()) {
    for (const auto& value : j) collect(value, name, hits);
  }
}
}  // namespace

SceneValue scene_parameter(const nlohmann::json& scene, const std::string& name,
                           const std::map<std::string, std::string>& pointers) {
  SceneValue out;
  const nlohmann::json* hit = nullptr;
  if (const auto it = pointers.find(name); it != pointers.end()) {
    const nlohmann::json::json_pointer ptr(it->second);
    if (!scene.contains(ptr)) {
      out.reason = "scene has no " + it->second;
      return out;
    }
    hit = &scene.at(ptr);
  } else {
    std::vector<const nlohmann::json*> hits;
    collect(scene, name, hits);
    if (hits.empty()) {
      out.reason = "scene has no key \"" + name + "\"";
      return out;
    }
    if (hits.size() > 1) {
      out.reason = "scene has " + std::to_string(hits.size()) + " keys \"" + name +
                   "\"; name one in /analysis/parameters";
      return out;
    }
    hit = hits.front();
  }
  if (!hit->is_number()) {
    out.reason = "scene parameter " + name + " is not a number";
    return out;
  }
  out.found = true;
  out.value = hit->get<double>();
  return out;
}

}  // namespace capsule::analysis
