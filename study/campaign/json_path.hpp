#pragma once
// Dotted paths into JSON objects ("resolution.a", "protocol.shear.kt"): how campaign
// sweeps and cases name the scene key they change.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace capsule::study {

// Splits "a.b.c" into {"a", "b", "c"}; throws std::invalid_argument on an empty component.
std::vector<std::string> split_dotted_path(const std::string& dotted);

// Sets target[a][b][c] = value, creating objects on the way. An object value is merged
// key by key into an existing object (so {"protocol": {"shear": {"kt": 5}}} keeps the
// other shear keys); anything else replaces. Throws std::invalid_argument when a path
// component runs into a non-object.
void set_at_dotted_path(nlohmann::json& target, const std::string& dotted, const nlohmann::json& value);

// Deep merge: objects merged key by key, everything else replaced.
void deep_merge(nlohmann::json& target, const nlohmann::json& patch);

}  // namespace capsule::study
