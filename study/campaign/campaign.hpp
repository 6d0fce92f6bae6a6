#pragma once
// A campaign file: a base scene, sweeps over scene keys, named cases, and the analysis
// block. Parsing only checks the campaign's own structure; expansion.hpp turns it into
// members and validates every member scene with the solver's own Scene validator.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace capsule::study {

// One swept scene key (a dotted path such as "Ca" or "resolution.a") and its values.
struct SweepAxis {
  std::string key;
  std::vector<nlohmann::json> values;
};

// "grid" axes combine as a Cartesian product; "zip" axes (all of one length) advance
// together. Both together: every grid point for every zip row.
struct Sweep {
  std::vector<SweepAxis> grid;
  std::vector<SweepAxis> zip;
  std::size_t count() const;  // members this sweep makes (1 for an empty sweep)
};

// A named variant of the base scene: "set" overrides keys (dotted paths or nested
// objects, merged), and an own "sweep" replaces the campaign's sweep for this case.
struct CampaignCase {
  std::string name;
  std::string description;
  nlohmann::json set = nlohmann::json::object();
  std::optional<Sweep> sweep;
};

struct Campaign {
  std::string name;          // safe path component: [A-Za-z0-9_.-]+, not starting with '.', <= 100 chars
  std::string description;
  std::string source;        // the file it came from (for messages)
  std::string text;          // the file's text as read (recorded in results/<name>/campaign.json)
  nlohmann::json base;       // a (partial) scene
  Sweep sweep;
  std::vector<CampaignCase> cases;  // empty: the base scene is the only case
  nlohmann::json analysis;          // null when the file has no analysis block
};

// Campaign and case names become folder names (results/<name>/, member slugs, and
// compare/<a>_vs_<b>/), so they are kept well under NAME_MAX (255).
inline constexpr std::size_t max_name_length = 100;

// True for names usable as one path component: [A-Za-z0-9_.-]+ not starting with '.',
// at most max_name_length characters.
bool is_safe_name(const std::string& name);

// Throws CampaignError naming the source, the JSON path and the problem.
Campaign parse_campaign(const std::string& text, const std::string& source);
Campaign load_campaign(const std::string& path);

}  // namespace capsule::study
