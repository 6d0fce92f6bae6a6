#pragma once
// What an error message adds for a user's slip: the operating system's reason a file cannot
// be opened (and the file meant, when adding ".json" finds one), the known key nearest to a
// misspelt one, and whether a JSON document is a scene or a campaign (given to the wrong
// program). Shared by `capsule` and `study`.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace capsule {

// Why `path` cannot be read as a file: "is a folder", or strerror of the open call
// ("No such file or directory"), followed by "; did you mean <path>.json?" when that exists.
// Empty when the file opens.
std::string unreadable_file_reason(const std::string& path);

// The known key closest to `key`: one equal to it with case, '_' and '-' ignored, else the
// nearest within two edits (one for a key shorter than six characters); empty when none is.
std::string nearest_key(const std::string& key, const std::vector<std::string>& known);

// "unknown key", with ", did you mean X?" when a known key is near.
std::string unknown_key_problem(const std::string& key, const std::vector<std::string>& known);

// What kind of document this is by its top-level keys: "campaign" (a "base" or "sweep" with no
// "dim"), "scene" (a "dim" with no "base"), or "" when neither is clear.
std::string document_kind(const nlohmann::json& document);

}  // namespace capsule
