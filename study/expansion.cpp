#include "study/expansion.hpp"

#include <algorithm>
#include <map>

#include "solver/scene/scene.hpp"
#include "solver/scene/version.hpp"
#include "study/campaign_error.hpp"
#include "study/json_path.hpp"
#include "study/member_id.hpp"

namespace capsule::study {

namespace {

using nlohmann::json;
using Assignment = std::vector<std::pair<std::string, json>>;

// Every point of a sweep, as key -> value assignments, grid varying fastest in its last key.
std::vector<Assignment> sweep_points(const Sweep& sweep) {
  std::vector<Assignment> points{Assignment{}};
  if (!sweep.zip.empty()) {
    points.clear();
    for (std::size_t row = 0; row < sweep.zip.front().values.size(); ++row) {
      Assignment a;
      for (const auto& axis : sweep.zip) a.emplace_back(axis.key, axis.values[row]);
      points.push_back(std::move(a));
    }
  }
  for (const auto& axis : sweep.grid) {
    std::vector<Assignment> next;
    for (const auto& p : points)
      for (const auto& v : axis.values) {
        Assignment a = p;
        a.emplace_back(axis.key, v);
        next.push_back(std::move(a));
      }
    points = std::move(next);
  }
  return points;
}

// The leaf key paths a case's "set" writes: {"resolution": {"a": 5}} -> "resolution.a".
void leaf_paths(const std::string& prefix, const json& value, std::vector<std::vector<std::string>>& out) {
  if (value.is_object() && !value.empty()) {
    for (auto it = value.begin(); it != value.end(); ++it)
      leaf_paths(prefix.empty() ? it.key() : prefix + "." + it.key(), it.value(), out);
  } else {
    out.push_back(split_dotted_path(prefix));
  }
}

// True when one path is the other or lies inside it ("resolution" and "resolution.a").
bool overlaps(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  const std::size_t n = std::min(a.size(), b.size());
  return std::equal(a.begin(), a.begin() + static_cast<long>(n), b.begin());
}

// A case that sets a key its sweep also varies is ambiguous (which wins?): refused.
void refuse_set_and_swept(const Campaign& campaign, const CampaignCase& cc, const Sweep& sweep) {
  std::vector<std::vector<std::string>> set_paths;
  for (auto it = cc.set.begin(); it != cc.set.end(); ++it) leaf_paths(it.key(), it.value(), set_paths);
  for (const auto* axes : {&sweep.grid, &sweep.zip})
    for (const auto& axis : *axes)
      for (const auto& path : set_paths)
        if (overlaps(split_dotted_path(axis.key), path))
          throw campaign_error(campaign.source, "cases",
                               "case \"" + cc.name + "\" sets \"" + axis.key + "\", which its sweep also varies",
                               "a key either set by the case or swept (give the case its own \"sweep\")");
}

std::string value_text(const json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

std::string describe(const std::string& case_name, const Assignment& point) {
  std::string d;
  if (!case_name.empty()) d = "case \"" + case_name + "\"";
  for (const auto& [key, value] : point) d += (d.empty() ? "" : ", ") + key + " = " + value.dump();
  return d.empty() ? "the base scene" : d;
}

}  // namespace

std::string member_slug(const std::string& case_name, const Assignment& parameters) {
  std::string slug = case_name;
  for (const auto& [key, value] : parameters) {
    const auto dot = key.rfind('.');
    const std::string short_key = dot == std::string::npos ? key : key.substr(dot + 1);
    slug += (slug.empty() ? "" : "-") + short_key + value_text(value);
  }
  for (char& c : slug) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                    c == '-' || c == '.';
    if (!ok) c = '_';
  }
  if (slug.empty()) slug = "member";
  if (slug.front() == '.') slug.front() = '_';
  constexpr std::size_t max_length = 80;  // keeps <slug>-<id> well under NAME_MAX (255)
  if (slug.size() > max_length) slug.resize(max_length);
  return slug;
}

std::vector<Member> expand_campaign(const Campaign& campaign) {
  std::vector<CampaignCase> cases = campaign.cases;
  if (cases.empty()) cases.push_back(CampaignCase{});

  std::vector<Member> members;
  std::map<std::string, std::pair<std::size_t, std::string>> index_by_id;  // id -> (member, description)
  for (const auto& cc : cases) {
    const Sweep& sweep = cc.sweep ? *cc.sweep : campaign.sweep;
    refuse_set_and_swept(campaign, cc, sweep);
    json case_scene = campaign.base;
    try {
      for (auto it = cc.set.begin(); it != cc.set.end(); ++it) set_at_dotted_path(case_scene, it.key(), it.value());
    } catch (const std::invalid_argument& e) {
      throw campaign_error(campaign.source, "cases", "case \"" + cc.name + "\": " + e.what());
    }
    for (const auto& point : sweep_points(sweep)) {
      json scene = case_scene;
      const std::string where = describe(cc.name, point);
      try {
        for (const auto& [key, value] : point) set_at_dotted_path(scene, key, value);
      } catch (const std::invalid_argument& e) {
        throw campaign_error(campaign.source, "sweep", where + ": " + e.what());
      }
      Member m;
      try {
        m.scene = Scene::from_json(scene, campaign.source + " [" + where + "]").to_json();
      } catch (const SceneError& e) {
        throw CampaignError(std::string("invalid member scene: ") + e.what());
      }
      m.index = members.size();
      m.case_name = cc.name;
      m.parameters = point;
      m.id = member_id(m.scene, physics_version);
      m.slug = member_slug(cc.name, point);
      if (auto it = index_by_id.find(m.id); it != index_by_id.end()) {
        Member& first = members[it->second.first];
        if (first.case_name == cc.name)
          throw campaign_error(campaign.source, "sweep",
                               where + " gives the same scene as " + it->second.second + " (member " + m.id + ")",
                               "every member of a case a different scene");
        first.other_cases.push_back(cc.name);
        continue;
      }
      index_by_id.emplace(m.id, std::make_pair(members.size(), where));
      members.push_back(std::move(m));
    }
  }
  return members;
}

}  // namespace capsule::study
