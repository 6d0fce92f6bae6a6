#include "study/campaign/json_path.hpp"

#include "common/json_text.hpp"

#include <stdexcept>

namespace capsule::study {

std::vector<std::string> split_dotted_path(const std::string& dotted) {
  std::vector<std::string> parts;
  std::string current;
  for (char c : dotted) {
    if (c == '.') {
      parts.push_back(current);
      current.clear();
    } else {
      current += c;
    }
  }
  parts.push_back(current);
  for (const auto& p : parts)
    if (p.empty()) throw std::invalid_argument(message_value(dotted) + " is not a key path (expected e.g. \"Ca\" or \"resolution.a\")");
  return parts;
}

void deep_merge(nlohmann::json& target, const nlohmann::json& patch) {
  if (patch.is_object() && target.is_object()) {
    for (auto it = patch.begin(); it != patch.end(); ++it) deep_merge(target[it.key()], it.value());
  } else {
    target = patch;
  }
}

void set_at_dotted_path(nlohmann::json& target, const std::string& dotted, const nlohmann::json& value) {
  const auto parts = split_dotted_path(dotted);
  nlohmann::json* node = &target;
  std::string walked;
  for (const auto& part : parts) {
    if (node->is_null()) *node = nlohmann::json::object();
    if (!node->is_object())
      throw std::invalid_argument(message_value(dotted) + ": " + message_value(walked) + " is a " + node->type_name() +
                                  ", not an object");
    walked += (walked.empty() ? "" : ".") + part;
    node = &(*node)[part];
  }
  deep_merge(*node, value);
}

}  // namespace capsule::study
