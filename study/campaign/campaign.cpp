#include "study/campaign/campaign.hpp"

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "analysis/report/analysis_block.hpp"
#include "common/json_text.hpp"
#include "solver/scene/user_hints.hpp"
#include "study/campaign/campaign_error.hpp"
#include "study/campaign/json_path.hpp"
#include "study/campaign/member_count.hpp"

namespace capsule::study {

namespace {

using nlohmann::json;

std::string index_path(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }
std::string key_path(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

void refuse_unknown_keys(const json& object, const std::set<std::string>& known, const std::string& source,
                         const std::string& path) {
  for (auto it = object.begin(); it != object.end(); ++it) {
    if (known.count(it.key())) continue;
    std::string list;
    for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
    throw campaign_error(source, key_path(path, it.key()),
                         unknown_key_problem(it.key(), std::vector<std::string>(known.begin(), known.end())),
                         "one of " + list);
  }
}

std::string read_string(const json& object, const std::string& key, bool required, const std::string& source,
                        const std::string& path) {
  if (!object.contains(key)) {
    if (required) throw campaign_error(source, key_path(path, key), "missing required key", "a string");
    return "";
  }
  const json& v = object.at(key);
  if (!v.is_string()) throw campaign_error(source, key_path(path, key), "is a " + std::string(v.type_name()), "a string");
  return v.get<std::string>();
}

std::string read_safe_name(const json& object, const std::string& source, const std::string& path) {
  const std::string name = read_string(object, "name", true, source, path);
  if (name.size() > max_name_length)
    throw campaign_error(source, key_path(path, "name"),
                         "a name of " + std::to_string(name.size()) + " characters is too long",
                         "at most " + std::to_string(max_name_length) + " characters");
  if (!is_safe_name(name))
    throw campaign_error(source, key_path(path, "name"), message_value(name) + " is not a safe name",
                         "letters, digits, '_', '-', '.', not starting with '.', at most " +
                             std::to_string(max_name_length) + " characters");
  return name;
}

void check_key_path(const std::string& key, const std::string& source, const std::string& path) {
  try {
    split_dotted_path(key);
  } catch (const std::invalid_argument& e) {
    throw campaign_error(source, path, e.what());
  }
}

std::vector<SweepAxis> read_axes(const json& object, const std::string& source, const std::string& path) {
  if (!object.is_object())
    throw campaign_error(source, path, "is a " + std::string(object.type_name()),
                         "an object {\"<scene key>\": [values...]}");
  std::vector<SweepAxis> axes;
  for (auto it = object.begin(); it != object.end(); ++it) {
    const std::string here = key_path(path, it.key());
    check_key_path(it.key(), source, here);
    if (!it.value().is_array())
      throw campaign_error(source, here, "is a " + std::string(it.value().type_name()), "a list of values");
    if (it.value().empty()) throw campaign_error(source, here, "empty sweep", "a list of at least one value");
    SweepAxis axis{it.key(), {}};
    for (const auto& v : it.value()) axis.values.push_back(v);
    axes.push_back(std::move(axis));
  }
  if (axes.empty()) throw campaign_error(source, path, "empty sweep", "at least one swept key");
  return axes;
}

Sweep read_sweep(const json& j, const std::string& source, const std::string& path) {
  if (!j.is_object())
    throw campaign_error(source, path, "is a " + std::string(j.type_name()), "an object with \"grid\" and/or \"zip\"");
  refuse_unknown_keys(j, {"grid", "zip"}, source, path);
  if (j.empty()) throw campaign_error(source, path, "empty sweep", "\"grid\" and/or \"zip\"");
  Sweep sweep;
  if (j.contains("grid")) sweep.grid = read_axes(j.at("grid"), source, key_path(path, "grid"));
  if (j.contains("zip")) {
    sweep.zip = read_axes(j.at("zip"), source, key_path(path, "zip"));
    const std::size_t n = sweep.zip.front().values.size();
    for (const auto& axis : sweep.zip)
      if (axis.values.size() != n)
        throw campaign_error(source, key_path(key_path(path, "zip"), axis.key),
                             "zip lists of unequal length: " + std::to_string(axis.values.size()) + " values, but \"" +
                                 sweep.zip.front().key + "\" has " + std::to_string(n),
                             "every zip list of the same length");
  }
  std::set<std::string> seen;
  for (const auto* axes : {&sweep.grid, &sweep.zip})
    for (const auto& axis : *axes)
      if (!seen.insert(axis.key).second)
        throw campaign_error(source, path, message_value(axis.key) + " is swept twice", "each key in one list only");
  return sweep;
}

json read_set(const json& j, const std::string& source, const std::string& path) {
  if (!j.is_object())
    throw campaign_error(source, path, "is a " + std::string(j.type_name()), "an object {\"<scene key>\": value}");
  for (auto it = j.begin(); it != j.end(); ++it) check_key_path(it.key(), source, key_path(path, it.key()));
  return j;
}

}  // namespace

std::size_t Sweep::count() const {
  std::size_t n = 1;
  for (const auto& axis : grid) n *= axis.values.size();
  if (!zip.empty()) n *= zip.front().values.size();
  return n;
}

bool is_safe_name(const std::string& name) {
  if (name.empty() || name.front() == '.' || name.size() > max_name_length) return false;
  for (char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                    c == '-' || c == '.';
    if (!ok) return false;
  }
  return true;
}

Campaign parse_campaign(const std::string& text, const std::string& source) {
  json doc;
  try {
    doc = parse_json_text(text, source);  // comments allowed, duplicate keys refused
  } catch (const JsonTextError& e) {
    throw CampaignError(e.what());
  }
  if (!doc.is_object())
    throw campaign_error(source, "", "the document is a " + std::string(doc.type_name()), "a JSON object");
  if (document_kind(doc) == "scene")
    throw campaign_error(source, "", "this is a scene file, not a campaign: run it with `capsule " + source +
                                         " -o member.h5`, or make it a campaign's \"base\"",
                         "a campaign {\"name\", \"base\", \"sweep\", ...}");
  refuse_unknown_keys(doc, {"name", "description", "base", "sweep", "cases", "analysis"}, source, "");

  Campaign c;
  c.source = source;
  c.text = text;
  c.name = read_safe_name(doc, source, "");
  c.description = read_string(doc, "description", false, source, "");
  if (!doc.contains("base")) throw campaign_error(source, "base", "missing required key", "a scene object");
  c.base = doc.at("base");
  if (!c.base.is_object())
    throw campaign_error(source, "base", "is a " + std::string(c.base.type_name()), "a scene object");
  if (doc.contains("sweep")) c.sweep = read_sweep(doc.at("sweep"), source, "sweep");

  if (doc.contains("cases")) {
    const json& cases = doc.at("cases");
    if (!cases.is_array() || cases.empty())
      throw campaign_error(source, "cases", cases.is_array() ? "empty list" : "is a " + std::string(cases.type_name()),
                           "a non-empty list of {\"name\", \"set\", \"sweep\"} objects");
    std::set<std::string> names;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const std::string path = index_path("cases", i);
      const json& cj = cases[i];
      if (!cj.is_object())
        throw campaign_error(source, path, "is a " + std::string(cj.type_name()), "an object {\"name\", \"set\", ...}");
      refuse_unknown_keys(cj, {"name", "description", "set", "sweep"}, source, path);
      CampaignCase cc;
      cc.name = read_safe_name(cj, source, path);
      if (!names.insert(cc.name).second)
        throw campaign_error(source, key_path(path, "name"), "case \"" + cc.name + "\" appears twice", "unique names");
      cc.description = read_string(cj, "description", false, source, path);
      if (cj.contains("set")) cc.set = read_set(cj.at("set"), source, key_path(path, "set"));
      if (cj.contains("sweep")) cc.sweep = read_sweep(cj.at("sweep"), source, key_path(path, "sweep"));
      c.cases.push_back(std::move(cc));
    }
  }

  if (doc.contains("analysis")) {
    c.analysis = doc.at("analysis");
    try {
      analysis::validate_analysis_block(c.analysis, source);
    } catch (const std::invalid_argument& e) {
      throw CampaignError(e.what());
    }
  }
  check_member_count(c);
  return c;
}

namespace {

// Campaign files of this name in the nearest existing folder of the path and one level below
// it (campaigns/ keeps the dissertation's campaigns at its top and groups the others:
// accuracy/, probes/), for a path that names one at another place.
std::string same_name_below(const std::filesystem::path& path) {
  std::error_code ec;
  std::filesystem::path folder = path.parent_path();
  while (!folder.empty() && !std::filesystem::is_directory(folder, ec)) folder = folder.parent_path();
  if (folder.empty()) folder = ".";
  std::string found;
  for (std::filesystem::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    if (it.depth() > 1) it.disable_recursion_pending();
    if (it->path().filename() == path.filename() && it->path() != path)
      found.append(found.empty() ? "" : " or ").append(it->path().string());
  }
  return found;
}

}  // namespace

Campaign load_campaign(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const std::string moved = same_name_below(path);
    throw campaign_error(path, "", "cannot open the campaign file: " + unreadable_file_reason(path),
                         moved.empty() ? "" : "a campaign file; this name is at " + moved);
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parse_campaign(text.str(), path);
}

}  // namespace capsule::study
