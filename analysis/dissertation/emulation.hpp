#pragma once
// THESIS.md's third column (docs/guide/dissertation_numerics.md): every claim row that differs,
// and every Table 2 coefficient, beside the toolkit run at the text's own settings, the emulation
// campaigns (campaigns/emulation/, "numerics": "dissertation"), whose results are in
// <results>/emulation_<campaign>/. The same rule runs on them as on the toolkit's campaigns.
//
// The reason a difference gets:
//  - the text's numerics: at the text's settings the rule agrees (the text's number comes back)
//    and converged it differs: a resolution or method artefact of the text;
//  - the model: at the text's settings it still differs: some part of the model or protocol
//    differs from the text's (which one: switch the preset's items one at a time);
//  - cannot tell: the emulation campaign is shipped but the rule cannot judge it;
//  - not run: no emulation campaign the rule reads is shipped.
#include <string>
#include <vector>

#include "analysis/dissertation/claims.hpp"
#include "analysis/dissertation/table2.hpp"

namespace capsule::analysis {

inline constexpr const char* k_emulation_prefix = "emulation_";

enum class EmulationReason { text_numerics, model, cannot_tell, not_run };
const char* emulation_reason_text(EmulationReason r);  // "the text's numerics", "the model", "cannot tell", "not run"

// One item of the preset switched back to the toolkit's value (scripts/emulation-campaigns writes
// these campaigns, emulation_<label>_<campaign>, for the 2D campaigns of the unexplained claims).
struct EmulationSwitch {
  std::string label;  // the campaign prefix is emulation_<label>_
  std::string item;   // "resolution.kernel = peskin4"
};
const std::vector<EmulationSwitch>& emulation_switches();

struct EmulationRow {
  std::size_t index = 0;  // the row's place in evaluate_claims' list
  ClaimResult toolkit;    // the toolkit's row (converged policy of evaluate_claims_at_two_levels)
  ClaimResult emulated;   // the same rule on the emulation campaigns
  EmulationReason reason = EmulationReason::not_run;
  std::string sentence;   // one generated sentence: what ran, what it gave, the reason
  // Per switch (emulation_switches' order): the same rule with that item switched back; verdict
  // cannot tell naming the missing campaign where it is not shipped.
  std::vector<ClaimResult> switched;
};

// The rows of `toolkit` that differ, each with the row of `emulated` at the same place (both from
// evaluate_claims, so in the same order); `shipped` says whether the emulation campaigns a row
// names (its `campaign`) include a shipped one. Throws std::logic_error when the lists do not match.
std::vector<EmulationRow> emulation_rows(const std::vector<ClaimResult>& toolkit, const std::vector<ClaimResult>& emulated,
                                         const std::vector<std::string>& shipped_campaigns);

// Adds to each row the row at its index of `switched_rows` (evaluate_claims on the campaigns of
// switch number `k`); rows are added in switch order. Throws std::logic_error on a size mismatch.
void attach_switch(std::vector<EmulationRow>& rows, const std::vector<ClaimResult>& switched_rows);

// One reason per claim (key) from its rows: the model when some row is, else the text's numerics
// when some row is, else cannot tell when some row is, else not run.
std::vector<std::pair<std::string, EmulationReason>> claim_emulation_reasons(const std::vector<EmulationRow>& rows);

struct EmulationCounts {
  int text_numerics = 0, model = 0, cannot_tell = 0, not_run = 0;  // claims
};
EmulationCounts count_emulation(const std::vector<EmulationRow>& rows);

// The first screen's line: "Of the N claims that differ, ...".
std::string emulation_count_line(const EmulationCounts& counts);

// The section: the rows that differ (the text / at the text's settings / converged / reason), a
// sentence per claim, and Table 2's coefficients at the text's settings beside the toolkit's.
std::string emulation_section_markdown(const std::vector<EmulationRow>& rows,
                                       const std::vector<Table2RowComparison>& toolkit_table2,
                                       const std::vector<Table2RowComparison>& emulated_table2);

}  // namespace capsule::analysis
