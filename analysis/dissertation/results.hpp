#pragma once
// The shipped results THESIS.md is written from: results/<campaign>/report/fits.json of
// every dissertation campaign, and the member files it names. A campaign without a
// fits.json, or a member whose file is gone, is recorded with why, never skipped silently.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/fit/member_fits.hpp"
#include "solver/io/member_file.hpp"

namespace capsule::analysis {

struct DissertationMember {
  std::string id, slug, case_name, status;    // status: the member file's, as fits.json recorded it
  std::map<std::string, double> parameters;   // as fits.json recorded them (Ca, E_b, V, eta, table x's)
  MemberFits fits;                            // parsed from fits.json
  std::string recorded_path;                  // fits.json's "path"
  std::string file;                           // resolved member.h5, "" when not found
  // A member of a resolution ladder with a finer member of the same physical point shipped:
  // the claims judge each point at its finest shipped level, as Table 2 takes the finest
  // level of a bilinear ladder. Its `finer` names that member.
  bool coarse = false;
  std::string finer;
};

struct DissertationCampaign {
  std::string name;
  bool found = false;
  std::string missing;  // why not found: "campaign X not run (no <dir>/X/report/fits.json)"
  nlohmann::json fits;
  std::vector<DissertationMember> members;
  // The campaign's resolution ladder keys (analysis ladder[].key, bilinear.ladder) with
  // their spacing ("1/x", "2^-x", "x"), read from fits.json's analysis block.
  std::map<std::string, std::string> ladder_keys;
  // Some physical point (or bilinear fit) of the campaign is shipped at two levels or more of a ladder.
  bool several_levels = false;

  // Members of one case ("" = every case), each slug once (a member shared by several
  // cases is listed in fits.json once per case), without the coarse members of a ladder.
  std::vector<const DissertationMember*> in_case(const std::string& case_name) const;
  // The same with the coarse members too.
  std::vector<const DissertationMember*> in_case_all_levels(const std::string& case_name) const;
  // "resolution.a: 7 (6 members), 5 (4 members)": the ladder levels the claims judge;
  // "" without a ladder.
  std::string judged_levels() const;
};

class DissertationResults {
 public:
  // level 0: each physical point judged at its finest shipped level of a ladder (and each bilinear
  // fit at its finest); level 1: at the next coarser level where the point has one, else its only.
  // campaign_prefix: read campaign X from <results_dir>/<prefix>X (the emulation campaigns,
  // emulation_X, run with the dissertation's numerics: analysis/dissertation/emulation.hpp).
  explicit DissertationResults(std::string results_dir, int level = 0, std::string campaign_prefix = "");
  const std::string& results_dir() const { return dir_; }
  int level() const { return level_; }
  // Loaded on first use and kept. Throws std::runtime_error for a fits.json that is not valid JSON.
  const DissertationCampaign& campaign(const std::string& name) const;
  // The campaigns asked for since the last call (the claims record which campaigns each rule read).
  std::set<std::string> take_campaigns_read() const;
  // The member file's contents; nullopt with `why` set when missing, unreadable or not
  // complete. With accept_unstable, a member that ended unstable is returned too (its rows
  // up to the blow-up are results: the text's own 3D recoveries end in instability).
  std::optional<io::MemberData> member_data(const DissertationMember& m, std::string& why,
                                            bool accept_unstable = false) const;

 private:
  std::string dir_;
  int level_ = 0;
  std::string prefix_;
  mutable std::map<std::string, DissertationCampaign> campaigns_;
  mutable std::set<std::string> read_;
};

// Where a member file recorded as `recorded` lives for a campaign whose results folder
// is `campaign_root`: a relative path is relative to that folder (shipped results); an
// absolute one that no longer exists (a clone elsewhere) is looked for as
// <campaign_root>/members/<its folder>/<its name>. "" when neither exists.
std::string resolve_member_file(const std::string& campaign_root, const std::string& recorded);

// Marks the coarse members of a campaign's ladders: members of one physical point (the same
// case and the same recorded parameters apart from the ladder keys) at a coarser level of a
// key than another member of that point. A member whose fits.json entry lacks the key's
// value is never coarse.
// With level 1 the member judged is each point's next coarser level (its only one where it has one)
// and every other member of the point is coarse; `finer` names the judged member for the levels
// coarser than it. Sets c.several_levels when some point has two levels or more.
void mark_coarse_members(DissertationCampaign& c, int level = 0);

// Level 1: drops each (case, target)'s first, finest, bilinear fit from c.fits where a coarser one
// follows it, so that the claims read the next coarser level's fit; sets c.several_levels then.
void judge_bilinear_at_level(DissertationCampaign& c, int level);

}  // namespace capsule::analysis
