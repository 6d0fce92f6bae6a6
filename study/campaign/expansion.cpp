#include "study/campaign/expansion.hpp"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

#include "solver/scene/scene.hpp"
#include "solver/scene/version.hpp"
#include "study/campaign/campaign_error.hpp"
#include "study/campaign/json_path.hpp"
#include "study/campaign/member_id.hpp"

namespace capsule::study {

namespace {

using nlohmann::json;
using Assignment = std::vector<std::pair<std::string, json>>;

// Point i of a sweep (0 <= i < sweep.count()), as key -> value assignments: zip rows
// outermost, then the grid axes in order, the last grid axis varying fastest. Computed
// from the index, so no list of points is ever held.
Assignment sweep_point(const Sweep& sweep, std::size_t i) {
  std::vector<std::size_t> grid_index(sweep.grid.size());
  for (std::size_t k = sweep.grid.size(); k-- > 0;) {
    const std::size_t n = sweep.grid[k].values.size();
    grid_index[k] = i % n;
    i /= n;
  }
  Assignment a;
  for (const auto& axis : sweep.zip) a.emplace_back(axis.key, axis.values[i]);
  for (std::size_t k = 0; k < sweep.grid.size(); ++k) a.emplace_back(sweep.grid[k].key, sweep.grid[k].values[grid_index[k]]);
  return a;
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

void for_each_member(const Campaign& campaign, const std::function<void(Member&&)>& visit,
                     const std::function<void(std::size_t, const std::string&)>& also_case) {
  std::vector<CampaignCase> cases = campaign.cases;
  if (cases.empty()) cases.push_back(CampaignCase{});

  // The duplicate check keeps 16 bytes per member: id hash -> (member index, case, point).
  struct Seen {
    std::size_t member;
    std::uint32_t case_index;
    std::size_t point;
  };
  std::unordered_map<std::uint64_t, Seen> seen;
  std::size_t next_index = 0;
  for (std::size_t ci = 0; ci < cases.size(); ++ci) {
    const CampaignCase& cc = cases[ci];
    const Sweep& sweep = cc.sweep ? *cc.sweep : campaign.sweep;
    refuse_set_and_swept(campaign, cc, sweep);
    json case_scene = campaign.base;
    try {
      for (auto it = cc.set.begin(); it != cc.set.end(); ++it) set_at_dotted_path(case_scene, it.key(), it.value());
    } catch (const std::invalid_argument& e) {
      throw campaign_error(campaign.source, "cases", "case \"" + cc.name + "\": " + e.what());
    }
    const std::size_t points = sweep.count();
    for (std::size_t pi = 0; pi < points; ++pi) {
      const Assignment point = sweep_point(sweep, pi);
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
      m.case_name = cc.name;
      m.parameters = point;
      m.id = member_id(m.scene);
      m.slug = member_slug(cc.name, point);
      const std::uint64_t hash = std::stoull(m.id, nullptr, 16);
      if (auto it = seen.find(hash); it != seen.end()) {
        const Seen& first = it->second;
        const CampaignCase& first_case = cases[first.case_index];
        if (first.case_index == ci) {
          const Sweep& first_sweep = first_case.sweep ? *first_case.sweep : campaign.sweep;
          throw campaign_error(campaign.source, "sweep",
                               where + " gives the same scene as " +
                                   describe(first_case.name, sweep_point(first_sweep, first.point)) + " (member " +
                                   m.id + ")",
                               "every member of a case a different scene");
        }
        also_case(first.member, cc.name);
        continue;
      }
      m.index = next_index++;
      seen.emplace(hash, Seen{m.index, static_cast<std::uint32_t>(ci), pi});
      visit(std::move(m));
    }
  }
}

std::vector<Member> expand_campaign(const Campaign& campaign) {
  std::vector<Member> members;
  for_each_member(
      campaign, [&members](Member&& m) { members.push_back(std::move(m)); },
      [&members](std::size_t index, const std::string& case_name) { members[index].other_cases.push_back(case_name); });
  return members;
}

}  // namespace capsule::study
