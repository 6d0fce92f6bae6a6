#include "study/run/script_path.hpp"

#include <cstdio>

namespace capsule::study {

void require_script_safe(const std::string& what, const std::filesystem::path& path) {
  const std::string text = path.string();
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c == 0x7f) {
      char byte[8];
      std::snprintf(byte, sizeof byte, "0x%02x", c);
      std::string shown;
      for (char d : text) shown += (static_cast<unsigned char>(d) < 0x20 || d == 0x7f) ? '?' : d;
      throw UnsafePathError(what + " contains a control character (byte " + byte + " at position " +
                            std::to_string(i) + "), refused in a generated script: " + shown);
    }
  }
}

}  // namespace capsule::study
