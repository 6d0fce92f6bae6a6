#pragma once
// Reading the JSON text of a scene or campaign file: // and /* */ comments are allowed
// (the campaign example of README.md and docs/guide/campaigns.md uses them), a key given twice in one object is refused (nlohmann would
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

// Objects and arrays nested deeper than this are refused (a scene or campaign needs four or
// five levels; without a bound, 100 000 nested arrays overflow the stack when printed).
inline constexpr std::size_t kMaxJsonDepth = 64;

nlohmann::json parse_json_text(const std::string& text, const std::string& source);

// A user's text as an error message shows it: control characters escaped (\u001b, \u0000; an
// ESC never reaches the terminal, a NUL never cuts the message) and, past kMessageChars, cut
// with its full length named.
inline constexpr std::size_t kMessageChars = 120;
// Control characters (and DEL) escaped as \u00XX, everything else as it is, uncut: a campaign's
// text as the terminal gets it (an ESC that would recolour it, a CR that would overwrite the line).
std::string escape_controls(const std::string& text);
// A message for the terminal: as escape_controls, but a line break stays one (messages of
// several lines); what a campaign or a file put in it never recolours or retitles the terminal.
std::string terminal_text(const std::string& text);
std::string message_text(const std::string& text);
// A JSON value as an error message shows it: its JSON text, escaped and cut as above.
std::string message_value(const nlohmann::json& value);

}  // namespace capsule
