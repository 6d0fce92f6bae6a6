#include "study/campaign/member_id.hpp"

#include <cstdio>

#include "solver/io/content_hash.hpp"

namespace capsule::study {

std::uint64_t fnv1a_64(std::string_view bytes) {
  io::Fnv1a64 hash;
  hash.add(bytes);
  return hash.value();
}

std::string member_hash_text(const nlohmann::json& canonical_scene, const std::string& physics_version) {
  return canonical_scene.dump() + "\nphysics_version=" + physics_version;
}

std::string member_id(const nlohmann::json& canonical_scene, const std::string& physics_version) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx",
                static_cast<unsigned long long>(fnv1a_64(member_hash_text(canonical_scene, physics_version))));
  return hex;
}

}  // namespace capsule::study
