// Resolution ladders (block "ladder"): ladder/<name>.md/.csv/.tex and fits.json "ladders",
// one row per group of members that differ only in the ladder's key and per quantity.
#include <cmath>
#include <filesystem>

#include "analysis/report/report_section.hpp"
#include "analysis/report/resolution_ladder.hpp"

namespace capsule::analysis {

namespace fs = std::filesystem;

namespace {

std::string levels_text(const LadderRow& row) {
  std::string out;
  for (auto it = row.levels.rbegin(); it != row.levels.rend(); ++it)  // coarse to fine, as a ladder is read
    out += (out.empty() ? "" : ", ") + format_number(it->x);
  return out;
}

std::string join(const std::vector<std::string>& parts, const std::string& sep) {
  std::string out;
  for (const auto& p : parts) out += (out.empty() ? "" : sep) + p;
  return out;
}

class LadderSection : public ReportSection {
 public:
  void write(const ReportContext& context, const fs::path& out_dir, ReportOutputs& outputs) const override {
    outputs.fits["ladders"] = nlohmann::json::array();
    for (const LadderSpec& spec : context.block.ladders) {
      const LadderReport report = ladder_report(context, spec);
      const std::string short_key = spec.key.substr(spec.key.rfind('.') + 1);
      Table t;
      t.title = spec.name + ": resolution ladder in " + spec.key + " (h = " + spec.spacing +
                "); Richardson extrapolation q(h) = q0 + C h^p through the three finest levels";
      t.header = {"group", "quantity", short_key + " levels", "finest " + short_key, "finest value",
                  "extrapolated", "order p", "order from", "error estimate", "relative error", "levels used", "note"};
      nlohmann::json lj{{"name", spec.name}, {"key", spec.key}, {"spacing", spec.spacing},
                        {"assumed_order", spec.assumed_order}, {"groups", nlohmann::json::array()},
                        {"unplaced", report.unplaced}};
      for (const LadderRow& row : report.rows) {
        const LadderLevelValue& finest = row.levels.front();
        const RichardsonResult& r = row.result;
        std::string note = row.refusal.empty() ? r.reason : row.refusal;
        if (!row.excluded.empty()) note += (note.empty() ? "" : "; ") + ("excluded: " + join(row.excluded, "; "));
        std::vector<std::string> cells{row.group, row.quantity, levels_text(row), format_number(finest.x),
                                       finest.has_value ? format_number(finest.value) : "n/a: " + finest.reason};
        nlohmann::json gj{{"group", row.group}, {"cases", row.cases}, {"quantity", row.quantity},
                          {"finest_level", finest.x}, {"ok", row.refusal.empty()}, {"note", note}};
        gj["levels"] = nlohmann::json::array();
        for (const auto& l : row.levels)
          gj["levels"].push_back({{"level", l.x},
                                  {"member", l.member->ref.slug},
                                  {"value", l.has_value ? json_number(l.value) : nlohmann::json(nullptr)},
                                  {"reason", l.has_value ? "" : l.reason}});
        if (finest.has_value) gj["finest_value"] = finest.value;
        if (row.refusal.empty()) {
          const double rel = r.extrapolated != 0.0 ? r.error_estimate / std::abs(r.extrapolated) : k_nan;
          const std::string source = r.order_observed ? "observed" : r.reason.rfind("two levels", 0) == 0
                                                                        ? "assumed (two levels)"
                                                                        : "none (levels agree)";
          cells.insert(cells.end(), {format_number(r.extrapolated), format_number(r.order), source,
                                     format_number(r.error_estimate),
                                     std::isfinite(rel) ? format_number(rel) : "n/a: extrapolated value 0",
                                     row.used_levels, note});
          gj["extrapolated"] = r.extrapolated;
          gj["order"] = r.order;
          gj["order_observed"] = r.order_observed;
          gj["error_estimate"] = r.error_estimate;
          gj["relative_error"] = json_number(rel);
          gj["levels_used"] = row.used_levels;
        } else {
          cells.insert(cells.end(), {"n/a: " + row.refusal, "", "", "", "", row.used_levels, note});
        }
        t.rows.push_back(cells);
        lj["groups"].push_back(gj);
      }
      for (const auto& u : report.unplaced)
        t.rows.push_back({"(not on a ladder)", "", "", "", "", "n/a: " + u, "", "", "", "", "", u});
      if (t.rows.empty()) t.rows.push_back({"(none)", "", "", "", "", "n/a: no members", "", "", "", "", "", ""});
      outputs.write_table(t, out_dir / "ladder", spec.name);
      outputs.fits["ladders"].push_back(lj);
    }
  }
};

}  // namespace

std::unique_ptr<ReportSection> ladder_section() { return std::make_unique<LadderSection>(); }

}  // namespace capsule::analysis
