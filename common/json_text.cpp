#include "common/json_text.hpp"

#include <cstdio>
#include <set>
#include <vector>

namespace capsule {

namespace {

using nlohmann::json;

// Where the parser is: one frame per open object or array.
struct Frame {
  bool is_array = false;
  std::set<std::string> keys;  // objects: keys seen so far
  std::string key;             // objects: the key of the value being parsed
  std::size_t index = 0;       // arrays: the index of the value being parsed
};

std::string path_of(const std::vector<Frame>& frames) {
  std::string path;
  for (const auto& f : frames) {
    if (f.is_array) path.append("[").append(std::to_string(f.index)).append("]");
    else if (!f.key.empty()) path.append(path.empty() ? "" : ".").append(f.key);
  }
  return path;
}

struct DuplicateKey {
  std::string path;
};

struct TooDeep {
  std::string path;
};


}  // namespace

json parse_json_text(const std::string& text, const std::string& source) {
  std::vector<Frame> frames;
  // After a value ends, an enclosing array moves to its next index.
  const auto value_done = [&frames] {
    if (!frames.empty() && frames.back().is_array) ++frames.back().index;
  };
  const json::parser_callback_t watch = [&](int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        if (frames.size() >= kMaxJsonDepth) throw TooDeep{path_of(frames)};
        frames.push_back(event == json::parse_event_t::array_start ? Frame{true, {}, {}, 0} : Frame{});
        break;
      case json::parse_event_t::key: {
        Frame& f = frames.back();
        f.key = parsed.get<std::string>();
        if (!f.keys.insert(f.key).second) throw DuplicateKey{path_of(frames)};
        break;
      }
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        frames.pop_back();
        value_done();
        break;
      case json::parse_event_t::value: value_done(); break;
    }
    return true;
  };
  try {
    return json::parse(text, watch, /*allow_exceptions=*/true, /*ignore_comments=*/true);
  } catch (const DuplicateKey& d) {
    throw JsonTextError(source + ": " + message_text(d.path) + ": key given twice (allowed: each key once per object)");
  } catch (const TooDeep& d) {
    throw JsonTextError(source + ": " + message_text(d.path.empty() ? "(top level)" : d.path) +
                        ": nested deeper than " + std::to_string(kMaxJsonDepth) +
                        " levels (allowed: at most " + std::to_string(kMaxJsonDepth) + " nested objects or arrays)");
  } catch (const json::exception& e) {  // parse_error, and out_of_range for a number overflow (1e400)
    std::string what = e.what();
    const auto bracket = what.find("] ");  // drop nlohmann's "[json.exception.parse_error.101] "
    if (what.rfind("[json.exception.", 0) == 0 && bracket != std::string::npos) what = what.substr(bracket + 2);
    // The frames still say where the parser was: the key whose value did not parse.
    std::string where = message_text(path_of(frames));
    if (where.empty()) where = "(top level)";
    std::string allowed;
    if (dynamic_cast<const json::out_of_range*>(&e) != nullptr)
      allowed = " (allowed: numbers of magnitude below 1.8e308)";
    else if (what.find("invalid literal") != std::string::npos || what.find("invalid number") != std::string::npos)
      allowed = " (allowed: a number, string, true, false, null, object or array; NaN and Infinity are not JSON)";
    throw JsonTextError(source + ": " + where + ": not valid JSON: " + message_text(what) + allowed);
  }
}

std::string escape_controls(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) {
      char code[8];
      std::snprintf(code, sizeof code, "\\u%04x", u);
      out += code;
    } else {
      out += c;
    }
  }
  return out;
}

std::string terminal_text(const std::string& text) {
  std::string out;
  std::size_t from = 0;
  for (std::size_t at; (at = text.find('\n', from)) != std::string::npos; from = at + 1)
    out.append(escape_controls(text.substr(from, at - from))).append("\n");
  return out.append(escape_controls(text.substr(from)));
}

std::string message_text(const std::string& text) {
  const std::string escaped = escape_controls(text);
  if (escaped.size() <= kMessageChars) return escaped;
  return escaped.substr(0, kMessageChars) + "... (" + std::to_string(text.size()) + " characters)";
}

std::string message_value(const nlohmann::json& value) {
  // A string in quotes with its own length; anything else as its JSON text (invalid UTF-8 is
  // replaced, not thrown).
  if (value.is_string()) return "\"" + message_text(value.get<std::string>()) + "\"";
  return message_text(value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
}

}  // namespace capsule
