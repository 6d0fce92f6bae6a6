#include "study/campaign/member_id.hpp"

#include <cstdio>

#include "solver/io/content_hash.hpp"
#include "solver/scene/version.hpp"

namespace capsule::study {

std::uint64_t fnv1a_64(std::string_view bytes) {
  io::Fnv1a64 hash;
  hash.add(bytes);
  return hash.value();
}

std::string member_hash_text(const nlohmann::json& canonical_scene, const std::string& physics_version) {
  if (!canonical_scene.is_object()) return canonical_scene.dump() + "\nphysics_version=" + physics_version;
  // The canonical scene carries its version (so the solver runs it); the hash keeps the text of
  // the scene without it and the version after it, as before the scene carried one.
  nlohmann::json scene = canonical_scene;
  scene.erase("physics_version");
  // What is only written (shapes, snapshots) does not change what runs: the hash reads those
  // keys at their defaults, the values every member had before they were left out, so no id
  // changed. output.interval_kt stays: the protocol's stop tests read the rows it spaces.
  if (auto out = scene.find("output"); out != scene.end() && out->is_object())
    for (const auto& entry : output_only_defaults().items())
      if (out->contains(entry.key())) (*out)[entry.key()] = entry.value();
  return scene.dump() + "\nphysics_version=" + physics_version;
}

const nlohmann::json& output_only_defaults() {
  static const nlohmann::json defaults = {{"shapes_at_kt", nlohmann::json::array()}, {"snapshots", "none"}};
  return defaults;
}

std::string member_id(const nlohmann::json& canonical_scene) {
  return member_id(canonical_scene, canonical_scene.value("physics_version", std::string(capsule::physics_version)));
}

std::string member_id(const nlohmann::json& canonical_scene, const std::string& physics_version) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx",
                static_cast<unsigned long long>(fnv1a_64(member_hash_text(canonical_scene, physics_version))));
  return hex;
}

}  // namespace capsule::study
