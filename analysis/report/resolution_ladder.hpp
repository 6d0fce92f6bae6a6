#pragma once
// A resolution ladder over a report's members (block "ladder"): members that differ only
// in one resolution key form a group; per group and quantity, the finest level's value,
// the Richardson extrapolation with the observed order from the three finest levels, and
// |finest - extrapolated| as the discretisation-error estimate. Shared by the ladder
// tables and by the accuracy analysis, which can take its reference from a ladder.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/report/report_context.hpp"
#include "analysis/fit/richardson.hpp"

namespace capsule::analysis {

struct LadderLevelValue {
  double x = 0.0;                        // the key's value (a, segments, mesh_level)
  const MemberAnalysis* member = nullptr;
  bool has_value = false;
  double value = 0.0;
  std::string reason;                    // why no value
};

struct LadderRow {  // one group and quantity
  std::string group;                     // label: cases and what sets the group apart
  std::vector<std::string> cases;
  nlohmann::json rest_scene;             // every member's scene without the ladder key
  std::string quantity;
  std::vector<LadderLevelValue> levels;  // finest (smallest h) first
  RichardsonResult result;               // result.ok false: `refusal` says why
  std::string refusal;                   // why there is no extrapolation ("" when result.ok)
  std::vector<std::string> excluded;     // "a = 7 (slug): reason" for levels without a value
  std::string used_levels;               // "10, 7, 5": the levels the result rests on
};

struct LadderReport {
  std::vector<LadderRow> rows;
  std::vector<std::string> unplaced;     // "<slug>: why it is on no ladder" (key missing, bad value)
};

// h of a level: "1/x" -> 1/x, "2^-x" -> 2^-x, "x" -> x (NaN when not positive).
double ladder_spacing(const std::string& spacing, double x);

LadderReport ladder_report(const ReportContext& context, const LadderSpec& spec);

}  // namespace capsule::analysis
