#pragma once
// A member's id: FNV-1a (64 bit) of its canonical scene text plus its physics version
// (the solver's, or the older one a scene names), printed as 16 hex digits. Same scene (any key order, any number spelling,
// defaults written or not, any output-only key) -> same id; any parameter or physics change -> a new id.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace capsule::study {

std::uint64_t fnv1a_64(std::string_view bytes);

// The text that is hashed: canonical scene JSON (sorted keys) without its "physics_version"
// key, with the output-only keys at their defaults, + "\nphysics_version=<v>".
std::string member_hash_text(const nlohmann::json& canonical_scene, const std::string& physics_version);

// The output-only scene keys under "output" (shapes_at_kt, snapshots) with their defaults:
// they decide what is written, not what runs, so a member that adds them keeps its id.
const nlohmann::json& output_only_defaults();

// 16 lower-case hex digits.
std::string member_id(const nlohmann::json& canonical_scene, const std::string& physics_version);
// The id of a canonical scene under the physics version it names (this solver's if none).
std::string member_id(const nlohmann::json& canonical_scene);

}  // namespace capsule::study
