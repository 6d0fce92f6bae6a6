#include "analysis/report/scene_parameter.hpp"

#include <vector>

#include "solver/scene/scene.hpp"

namespace capsule::analysis {

namespace {
struct Hit {
  const nlohmann::json* value;
  std::string pointer;
};
void collect(const nlohmann::json& j, const std::string& name, const std::string& at, std::vector<Hit>& hits) {
  if (j.is_object()) {
    for (const auto& [key, value] : j.items()) {
      const std::string here = at + "/" + key;
      if (key == name) hits.push_back({&value, here});
      collect(value, name, here, hits);
    }
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) collect(j[i], name, at + "/" + std::to_string(i), hits);
  }
}
std::string dotted_to_pointer(const std::string& dotted) {
  std::string p = "/" + dotted;
  for (char& c : p)
    if (c == '.') c = '/';
  return p;
}
}  // namespace

SceneValue scene_parameter(const nlohmann::json& scene, const std::string& name,
                           const std::map<std::string, std::string>& pointers) {
  SceneValue out;
  const nlohmann::json* hit = nullptr;
  const auto it = pointers.find(name);
  if (it != pointers.end() || name.find('.') != std::string::npos) {
    const std::string text = it != pointers.end() ? it->second : dotted_to_pointer(name);
    const nlohmann::json::json_pointer ptr(text);
    if (!scene.contains(ptr)) {
      out.reason = "scene has no " + text;
      return out;
    }
    hit = &scene.at(ptr);
    out.pointer = text;
  } else {
    std::vector<Hit> hits;
    collect(scene, name, "", hits);
    if (hits.empty()) {
      out.reason = "scene has no key \"" + name + "\"";
      return out;
    }
    if (hits.size() > 1) {
      out.reason = "scene has " + std::to_string(hits.size()) + " keys \"" + name +
                   "\"; name one in /analysis/parameters";
      return out;
    }
    hit = hits.front().value;
    out.pointer = hits.front().pointer;
  }
  if (!hit->is_number()) {
    out.reason = "scene parameter " + name + " is not a number";
    return out;
  }
  out.found = true;
  out.value = hit->get<double>();
  return out;
}

const nlohmann::json* scene_value_at(const nlohmann::json& scene, const std::string& dotted_key) {
  const nlohmann::json::json_pointer ptr(dotted_to_pointer(dotted_key));
  if (scene.contains(ptr)) return &scene.at(ptr);
  // An absent key a canonical scene leaves out at its default means that default.
  if (const auto* d = omitted_scene_defaults(scene))
    if (const auto it = d->find(dotted_key); it != d->end()) return &it->second;
  return nullptr;
}

const std::map<std::string, nlohmann::json>* omitted_scene_defaults(const nlohmann::json& scene) {
  if (!scene.is_object() || !scene.contains("resolution") || !scene.contains("dim") || !scene["dim"].is_number())
    return nullptr;
  return &Scene::omitted_defaults(scene["dim"].get<int>());
}

nlohmann::json scene_without(const nlohmann::json& scene, const std::string& pointer) {
  nlohmann::json out = scene;
  if (pointer.empty()) return out;
  const nlohmann::json::json_pointer ptr(pointer);
  if (!out.contains(ptr)) return out;
  const nlohmann::json::json_pointer parent = ptr.parent_pointer();
  nlohmann::json& holder = out.at(parent);
  if (holder.is_object()) holder.erase(ptr.back());
  else holder.at(ptr) = nullptr;
  return out;
}

}  // namespace capsule::analysis
