#pragma once
// `study run --where KEY=VALUE`: run only the members whose canonical scene has VALUE at the
// dotted KEY, e.g. `--where resolution.a=5` runs the cheap level of a resolution ladder first
// (the rest runs later, and nothing finished is run again). VALUE is read as JSON when it
// parses (5, 0.2, "single", [10,10,8]) and as a plain string otherwise (single); numbers
// compare by value (5 matches 5.0). Several --where must all hold.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace capsule::study {

struct SceneCondition {
  std::string key;        // dotted scene key
  nlohmann::json value;   // what it must equal
  std::string text;       // as the user wrote it, for messages
};

// Parses "KEY=VALUE"; throws std::invalid_argument naming the text and what is wrong.
SceneCondition parse_scene_condition(const std::string& text);

// True when every condition holds for this canonical scene (a scene without the key fails it).
bool scene_matches(const nlohmann::json& scene, const std::vector<SceneCondition>& conditions);

}  // namespace capsule::study
