#include "solver/io/content_hash.hpp"

#include <cstdio>

namespace capsule::io {

std::string Fnv1a64::hex() const {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash_));
  return text;
}

void ContentDigest::add(const std::string& name, char kind, const void* bytes, std::size_t size) {
  Fnv1a64 h;
  h.add(&kind, 1);
  const std::uint64_t n = size;
  h.add(&n, sizeof n);
  h.add(bytes, size);
  parts_[name] = h.value();
}

std::string ContentDigest::hex() const {
  Fnv1a64 h;
  for (const auto& [name, part] : parts_) {
    h.add(name);
    h.add("\0", 1);
    h.add(&part, sizeof part);
  }
  return h.hex();
}

}  // namespace capsule::io
