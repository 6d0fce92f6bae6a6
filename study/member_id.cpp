#include "study/member_id.hpp"

#include <cstdio>

namespace capsule::study {

std::uint64_t fnv1a_64(std::string_view bytes) {
  std::uint64_t hash = 14695981039346656037ull;  // FNV-1a 64-bit offset basis
  for (unsigned char c : bytes) {
    hash ^= c;
    hash *= 1099511628211ull;  // FNV-1a 64-bit prime
  }
  return hash;
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
