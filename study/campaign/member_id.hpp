#pragma once
// A member's id: FNV-1a (64 bit) of its canonical scene text plus its physics version
// (the solver's, or the older one a scene names), printed as 16 hex digits. Same scene (any key order, any number spelling,
// defaults written or not) -> same id; any parameter or physics change -> a new id.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace capsule::study {

std::uint64_t fnv1a_64(std::string_view bytes);

// The text that is hashed: canonical scene JSON (sorted keys) without its "physics_version"
// key + "\nphysics_version=<v>".
std::string member_hash_text(const nlohmann::json& canonical_scene, const std::string& physics_version);

// 16 lower-case hex digits.
std::string member_id(const nlohmann::json& canonical_scene, const std::string& physics_version);
// The id of a canonical scene under the physics version it names (this solver's if none).
std::string member_id(const nlohmann::json& canonical_scene);

}  // namespace capsule::study
