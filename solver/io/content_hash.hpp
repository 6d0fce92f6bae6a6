#pragma once
// FNV-1a (64 bit): the toolkit's one hash. Member ids (study/campaign/member_id.hpp), the binary's
// fingerprint in restart points, and the content hash of member files use it. It detects
// damage and accidental change; it is not meant to resist someone forging a file.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>

namespace capsule::io {

class Fnv1a64 {
 public:
  void add(const void* bytes, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(bytes);
    for (std::size_t i = 0; i < size; ++i) {
      hash_ ^= p[i];
      hash_ *= 1099511628211ull;  // FNV-1a 64-bit prime
    }
  }
  void add(std::string_view text) { add(text.data(), text.size()); }
  std::uint64_t value() const { return hash_; }
  std::string hex() const;  // 16 lower-case hex digits

 private:
  std::uint64_t hash_ = 14695981039346656037ull;  // FNV-1a 64-bit offset basis
};

// The content hash of a file made of named parts (attributes, datasets): each part is hashed
// with its name, its kind (one letter) and its bytes, and the parts are combined in name
// order, so the writer and a reader get the same hash whatever order they visit them in.
class ContentDigest {
 public:
  void add(const std::string& name, char kind, const void* bytes, std::size_t size);
  std::string hex() const;

 private:
  std::map<std::string, std::uint64_t> parts_;
};

}  // namespace capsule::io
