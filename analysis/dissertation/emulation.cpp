#include "analysis/dissertation/emulation.hpp"

#include <map>
#include <stdexcept>

#include "analysis/dissertation/chapter_tables.hpp"
#include "analysis/dissertation/document_links.hpp"
#include "analysis/fit/number_format.hpp"
#include "analysis/report/table.hpp"

namespace capsule::analysis {

const char* emulation_reason_text(EmulationReason r) {
  switch (r) {
    case EmulationReason::text_numerics: return "the text's numerics";
    case EmulationReason::model: return "the model";
    case EmulationReason::cannot_tell: return "cannot tell";
    case EmulationReason::not_run: return "not run";
  }
  return "";
}

const std::vector<EmulationSwitch>& emulation_switches() {
  static const std::vector<EmulationSwitch> s = {{"Re", "Re = 0.05"},
                                                 {"a10", "resolution.a = 10"},
                                                 {"kernel", "resolution.kernel = peskin4"},
                                                 {"E_b_2d", "conventions.E_b_2d = dimensionless"},
                                                 {"biconcave_2d", "conventions.biconcave_2d = equivalent"}};
  return s;
}

namespace {

inline constexpr std::size_t k_cell = 160;  // a cell's characters; the whole text is in the claim's section

bool reads_shipped(const ClaimResult& row, const std::vector<std::string>& shipped) {
  for (const auto& name : shipped)
    if (row.campaign.find(name) != std::string::npos) return true;
  return false;
}

EmulationReason reason_of(const ClaimResult& emulated, bool shipped) {
  if (emulated.verdict == Verdict::agrees) return EmulationReason::text_numerics;
  if (emulated.verdict == Verdict::differs) return EmulationReason::model;
  return shipped ? EmulationReason::cannot_tell : EmulationReason::not_run;
}

std::string sentence_of(const EmulationRow& r) {
  const std::string what = r.toolkit.key + " (" + r.toolkit.campaign + ")";
  switch (r.reason) {
    case EmulationReason::text_numerics:
      return what + ": at the text's settings the rule agrees (" + clip_text(r.emulated.measured, k_cell) +
             "), converged it differs: the difference is the text's numerics.";
    case EmulationReason::model:
      return what + ": at the text's settings the rule still differs (" + clip_text(r.emulated.measured, k_cell) +
             "): a part of the model or protocol differs from the text's.";
    case EmulationReason::cannot_tell:
      return what + ": the emulation is shipped but the rule cannot judge it (" + clip_text(r.emulated.measured, k_cell) + ").";
    case EmulationReason::not_run:
      return what + ": not run at the text's settings (its emulation campaign is not shipped).";
  }
  return "";
}

int rank(EmulationReason r) {
  switch (r) {
    case EmulationReason::model: return 3;
    case EmulationReason::text_numerics: return 2;
    case EmulationReason::cannot_tell: return 1;
    case EmulationReason::not_run: return 0;
  }
  return 0;
}

// "verdict: measured", the verdict once where the measured text opens with it already.
std::string verdict_cell(const ClaimResult& row, std::size_t limit) {
  const std::string verdict = verdict_text(row.verdict);
  if (row.measured.rfind(verdict, 0) == 0) return clip_text(row.measured, limit);
  return verdict + ": " + clip_text(row.measured, limit);
}

std::string coefficient_cell(const Table2RowComparison& row, std::size_t k) {
  if (!row.found) return "not run";
  if (k >= row.coefficients.size() || !row.coefficients[k].measured) return "no fit";
  const auto& c = row.coefficients[k];
  return format_number(c.value) + " ± " + format_number(c.half_width);
}

Table table2_emulation_table(const std::vector<Table2RowComparison>& toolkit, const std::vector<Table2RowComparison>& emulated) {
  Table t;
  t.header = {"Table 2 row", "coefficient", "the text", "at the text's settings", "the toolkit (finest level)"};
  for (std::size_t i = 0; i < toolkit.size(); ++i) {
    const Table2RowComparison& tk = toolkit[i];
    if (!tk.reference) continue;
    const Table2Row& ref = *tk.reference;
    const std::string row = ref.target + " (Ca " + format_number(ref.Ca) + ", E_b " + format_number(ref.E_b) + ")";
    const double text[3] = {ref.a, ref.b, ref.c}, text_hw[3] = {ref.a_half_width, ref.b_half_width, ref.c_half_width};
    for (std::size_t k = 0; k < 3; ++k)
      t.rows.push_back({row, std::string(1, "abc"[k]), format_number(text[k]) + " ± " + format_number(text_hw[k]),
                        i < emulated.size() ? coefficient_cell(emulated[i], k) : "not run", coefficient_cell(tk, k)});
  }
  return t;
}

// The rows judged at the text's settings with some switch shipped: the verdict as each item alone
// goes back to the toolkit's value ("" when no row has any).
std::string switch_table_markdown(const std::vector<EmulationRow>& rows) {
  Table t;
  t.header = {"claim", "at the text's settings"};
  for (const auto& s : emulation_switches()) t.header.push_back("with " + s.item);
  for (const auto& r : rows) {
    bool any = false;
    for (const auto& sw : r.switched) any = any || sw.measured.find(" not run (no ") == std::string::npos;
    if (!any || r.reason == EmulationReason::not_run) continue;
    std::vector<std::string> row = {anchor_link(r.toolkit.key, claim_anchor(r.toolkit.key)),
                                    verdict_cell(r.emulated, 80)};
    for (const auto& sw : r.switched)
      row.push_back(sw.measured.find(" not run (no ") != std::string::npos
                        ? "not run"
                        : verdict_cell(sw, 80));
    t.rows.push_back(row);
  }
  if (t.rows.empty()) return "";
  return "\nWhich item moves a claim: the same rule with one item of the preset switched back to the toolkit's value "
         "(campaigns/emulation/switches/, the 2D campaigns of the claims with no measured cause):\n\n" + t.to_markdown();
}

}  // namespace

std::vector<EmulationRow> emulation_rows(const std::vector<ClaimResult>& toolkit, const std::vector<ClaimResult>& emulated,
                                         const std::vector<std::string>& shipped_campaigns) {
  if (toolkit.size() != emulated.size())
    throw std::logic_error("emulation_rows: " + std::to_string(toolkit.size()) + " toolkit rows against " +
                           std::to_string(emulated.size()) + " emulated ones");
  std::vector<EmulationRow> rows;
  for (std::size_t i = 0; i < toolkit.size(); ++i) {
    if (toolkit[i].key != emulated[i].key)
      throw std::logic_error("emulation_rows: row " + std::to_string(i) + " is " + toolkit[i].key + " and " + emulated[i].key);
    if (toolkit[i].verdict != Verdict::differs) continue;
    EmulationRow r;
    r.index = i;
    r.toolkit = toolkit[i];
    r.emulated = emulated[i];
    r.reason = reason_of(emulated[i], reads_shipped(toolkit[i], shipped_campaigns));
    r.sentence = sentence_of(r);
    rows.push_back(std::move(r));
  }
  return rows;
}

void attach_switch(std::vector<EmulationRow>& rows, const std::vector<ClaimResult>& switched_rows) {
  for (auto& r : rows) {
    if (r.index >= switched_rows.size() || switched_rows[r.index].key != r.toolkit.key)
      throw std::logic_error("attach_switch: the switched rows are not the toolkit's rules");
    r.switched.push_back(switched_rows[r.index]);
  }
}

std::vector<std::pair<std::string, EmulationReason>> claim_emulation_reasons(const std::vector<EmulationRow>& rows) {
  std::vector<std::pair<std::string, EmulationReason>> out;
  for (const auto& r : rows) {
    if (out.empty() || out.back().first != r.toolkit.key) out.emplace_back(r.toolkit.key, r.reason);
    else if (rank(r.reason) > rank(out.back().second)) out.back().second = r.reason;
  }
  return out;
}

EmulationCounts count_emulation(const std::vector<EmulationRow>& rows) {
  EmulationCounts c;
  for (const auto& [key, reason] : claim_emulation_reasons(rows))
    ++(reason == EmulationReason::text_numerics ? c.text_numerics
       : reason == EmulationReason::model       ? c.model
       : reason == EmulationReason::cannot_tell ? c.cannot_tell
                                                : c.not_run);
  return c;
}

std::string emulation_count_line(const EmulationCounts& c) {
  const int total = c.text_numerics + c.model + c.cannot_tell + c.not_run;
  return "Of the " + std::to_string(total) + " claims that differ (in every row or in some), run again at the text's own settings "
         "([the dissertation's numerics](#the-dissertations-numerics)): " + std::to_string(c.text_numerics) +
         " come back to the text's numbers (the difference is the text's numerics), " + std::to_string(c.model) +
         " still differ (the model), " + std::to_string(c.cannot_tell) + " cannot tell, " + std::to_string(c.not_run) +
         " not run yet.";
}

std::string emulation_section_markdown(const std::vector<EmulationRow>& rows,
                                       const std::vector<Table2RowComparison>& toolkit_table2,
                                       const std::vector<Table2RowComparison>& emulated_table2) {
  std::string md = "<a id=\"the-dissertations-numerics\"></a>\n\n## The dissertation's numerics\n\n";
  md += "Each claim row that differs, with the same rule run on the emulation campaigns: the dissertation's campaigns "
        "with `\"numerics\": \"dissertation\"` (the text's cosine delta, MRT rates, markers on the membrane, Reynolds "
        "number, one resolution (a = 10; the 2D circle a = 20) and its printed readings; what is not emulated and why: "
        "docs/guide/dissertation_numerics.md), shipped in `emulation_<campaign>/`. *the text's numerics*: at the text's "
        "settings the rule agrees, converged it differs; *the model*: at the text's settings it still differs; *not run*: "
        "the emulation campaign is not shipped (campaigns/emulation/, `study run` it).\n\n";
  md += emulation_count_line(count_emulation(rows)) + "\n\n";
  Table t;
  t.header = {"claim", "the text", "at the text's settings", "the toolkit converged", "reason"};
  for (const auto& r : rows) {
    const std::string text = r.toolkit.text_numbers.empty() ? r.toolkit.statement : r.toolkit.text_numbers;
    t.rows.push_back({anchor_link(r.toolkit.key, claim_anchor(r.toolkit.key)), clip_text(text, k_cell),
                      r.reason == EmulationReason::not_run ? std::string("not run") : verdict_cell(r.emulated, k_cell),
                      verdict_cell(r.toolkit, k_cell), emulation_reason_text(r.reason)});
  }
  md += t.to_markdown() + "\n";
  md += "In one sentence each:\n\n";
  for (const auto& r : rows) md += "- " + r.sentence + "\n";
  md += switch_table_markdown(rows);
  md += "\nTable 2 at the text's settings (the bilinear fits of `emulation_ch5_bilinear_*`, a = 10, one level) beside the "
        "toolkit's finest level:\n\n";
  md += table2_emulation_table(toolkit_table2, emulated_table2).to_markdown() + "\n";
  return md;
}

}  // namespace capsule::analysis
