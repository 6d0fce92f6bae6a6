#pragma once
// Reading the JSON text of a scene or campaign file: // and /* */ comments are allowed
// (README's examples use them), a key given twice in one object is refused (nlohmann would
// keep the last one silently), and every problem -- syntax, number overflow (1e400),
// duplicate key -- is reported with the file's name.
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace capsule {

// what() reads "<source>: <json path>: <problem>" (path "(top level)" for syntax errors).
struct JsonTextError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

nlohmann::json parse_json_text(const std::string& text, const std::string& source);

}  // namespace capsule
