#include "solver/scene/user_hints.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace capsule {

std::string unreadable_file_reason(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return "is a folder";
  errno = 0;
  if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
    std::fclose(f);
    return "";
  }
  std::string reason = errno != 0 ? std::strerror(errno) : "cannot be opened";
  const std::string with_json = path + ".json";
  if (path.size() < 5 || path.compare(path.size() - 5, 5, ".json") != 0)
    if (std::filesystem::is_regular_file(with_json, ec)) reason += "; did you mean " + with_json + "?";
  return reason;
}

namespace {

std::string folded(const std::string& s) {
  std::string out;
  for (char c : s)
    if (c != '_' && c != '-') out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string nearest_key(const std::string& key, const std::vector<std::string>& known) {
  for (const auto& k : known)
    if (folded(k) == folded(key)) return k;
  std::string best;
  std::size_t best_distance = std::max<std::size_t>(1, std::min<std::size_t>(2, key.size() / 3)) + 1;
  for (const auto& k : known)
    if (const std::size_t d = edit_distance(folded(key), folded(k)); d < best_distance) {
      best = k;
      best_distance = d;
    }
  return best;
}

std::string unknown_key_problem(const std::string& key, const std::vector<std::string>& known) {
  const std::string near = nearest_key(key, known);
  return near.empty() ? "unknown key" : "unknown key, did you mean " + near + "?";
}

std::string document_kind(const nlohmann::json& document) {
  if (!document.is_object()) return "";
  const bool campaign_keys = document.contains("base") || document.contains("sweep") || document.contains("cases");
  if (campaign_keys && !document.contains("dim")) return "campaign";
  if (document.contains("dim") && !campaign_keys) return "scene";
  return "";
}

}  // namespace capsule
