#include "study/campaign/member_filter.hpp"

#include <cmath>
#include <stdexcept>

#include "study/campaign/json_path.hpp"

namespace capsule::study {

namespace {
bool same_value(const nlohmann::json& a, const nlohmann::json& b) {
  if (a.is_number() && b.is_number()) return a.get<double>() == b.get<double>();
  if (a.is_array() && b.is_array()) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (!same_value(a[i], b[i])) return false;
    return true;
  }
  return a == b;
}
}  // namespace

SceneCondition parse_scene_condition(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw std::invalid_argument("--where \"" + text + "\": expected KEY=VALUE, e.g. resolution.a=5");
  SceneCondition c;
  c.key = text.substr(0, eq);
  c.text = text;
  split_dotted_path(c.key);  // throws on an empty component
  const std::string value = text.substr(eq + 1);
  c.value = nlohmann::json::parse(value, nullptr, /*allow_exceptions=*/false);
  if (c.value.is_discarded()) c.value = value;  // a bare word: a string
  return c;
}

bool scene_matches(const nlohmann::json& scene, const std::vector<SceneCondition>& conditions) {
  for (const auto& c : conditions) {
    const nlohmann::json* at = &scene;
    for (const auto& part : split_dotted_path(c.key)) {
      if (!at->is_object() || !at->contains(part)) return false;
      at = &(*at)[part];
    }
    if (!same_value(*at, c.value)) return false;
  }
  return true;
}

}  // namespace capsule::study
