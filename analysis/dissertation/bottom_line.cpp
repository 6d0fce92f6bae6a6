#include "analysis/dissertation/bottom_line.hpp"

#include <algorithm>
#include <map>

#include "analysis/dissertation/chapter_story.hpp"
#include "analysis/dissertation/chapter_tables.hpp"
#include "analysis/dissertation/deviations.hpp"
#include "analysis/dissertation/document_links.hpp"
#include "analysis/dissertation/report.hpp"

namespace capsule::analysis {

namespace {

// " (Ch. 2: 2, Ch. 3: 11)": how many claims of each chapter have the verdict (chapters with none left out).
std::string by_chapter(const std::map<std::string, std::map<ClaimVerdict, int>>& counts, ClaimVerdict v) {
  std::string list;
  for (const auto& chapter : text_chapters()) {
    const auto n = counts.find(chapter.number);
    if (n == counts.end() || !n->second.count(v) || n->second.at(v) == 0) continue;
    append_listed(list, "Ch. " + chapter.number + ": " + std::to_string(n->second.at(v)));
  }
  return list.empty() ? "" : " (" + list + ")";
}

// "1 claim" / "5 claims".
std::string claims_count(int n) { return std::to_string(n) + (n == 1 ? " claim" : " claims"); }
// "1 claim agrees", "2 claims agree": the verb follows the count
std::string claims_verb(int n, const std::string& plural_verb, const std::string& singular_verb) {
  return claims_count(n) + " " + (n == 1 ? singular_verb : plural_verb);
}

}  // namespace

std::string bottom_line_markdown(const std::vector<ClaimResult>& rows, const DissertationSummary& s, const std::vector<CauseGrade>& grades) {
  const auto verdicts = claim_verdicts(rows);
  std::map<std::string, std::string> chapter_of;
  for (const auto& r : rows) chapter_of.emplace(r.key, claim_chapter(r));
  std::map<std::string, std::map<ClaimVerdict, int>> by_chapter_counts;
  std::map<ClaimVerdict, std::vector<std::string>> keys_with;
  std::map<std::size_t, int> differing_per_cause;  // claims that differ or hold in part whose gap a cause closes in part
  for (const auto& [key, v] : verdicts) {
    ++by_chapter_counts[chapter_of[key]][v];
    keys_with[v].push_back(key);
    if (v == ClaimVerdict::differs || v == ClaimVerdict::in_part)
      for (const CauseGrade* g : grades_of_claim(grades, key))
        if (explains(*g)) ++differing_per_cause[g->cause];
  }

  const auto number_of = [&keys_with](ClaimVerdict v) { return static_cast<int>(keys_with[v].size()); };
  std::string md = "**Bottom line** (the dissertation's " + claims_count(static_cast<int>(verdicts.size())) +
                   " against the shipped results):\n\n";
  md += "- **Reproduced:** " + claims_verb(number_of(ClaimVerdict::agrees), "agree", "agrees") + by_chapter(by_chapter_counts, ClaimVerdict::agrees) + ".\n";
  md += "- **Not reproduced:** " + claims_verb(number_of(ClaimVerdict::differs), "differ", "differs") + by_chapter(by_chapter_counts, ClaimVerdict::differs);
  if (number_of(ClaimVerdict::in_part) > 0)
    md += ", and " + claims_verb(number_of(ClaimVerdict::in_part), "hold", "holds") + " only in part (the rows of one claim disagree): " +
          claim_links(keys_with[ClaimVerdict::in_part]);
  md += ".\n";
  md += "- **Cannot tell:** " + claims_count(number_of(ClaimVerdict::cannot_tell)) + ", for want of a campaign, a member or a result converged in resolution";
  if (number_of(ClaimVerdict::cannot_tell) > 0) md += ": " + claim_links(keys_with[ClaimVerdict::cannot_tell]);
  md += ".\n";
  md += "- **Table 2:** " + std::to_string(s.coefficients_overlap) + " of 18 coefficients share a point of their 95 % interval with the text's; " +
        std::to_string(s.coefficients_extrapolated_pass) + " of " +
        std::to_string(s.coefficients_extrapolated_pass + s.coefficients_extrapolated_fail) +
        " extrapolated over the ladder pass the difference test (|difference| <= 1.96 combined sigma); from the next coarser level "
        "to the finest " + std::to_string(s.coefficients_toward) + " move toward the text, " + std::to_string(s.coefficients_away) + " away.\n";
  md += "- **The text against its own rules:** the text's printed numbers pass the rule of " + claims_count(s.text_passes) +
        ", fail that of " + claims_count(s.text_fails) + "; " + std::to_string(s.text_no_numbers) +
        " claims rest on figures alone (no numbers to run the rule on).\n";
  // The known causes behind the most differences, most first (ties in the order of deviations.md).
  std::vector<std::pair<std::size_t, int>> causes(differing_per_cause.begin(), differing_per_cause.end());
  std::stable_sort(causes.begin(), causes.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  if (causes.size() > 3) causes.resize(3);
  if (!causes.empty()) {
    std::string list;
    for (const auto& [n, count] : causes)
      append_listed(list, anchor_link(cause_label(n) + " " + known_deviations()[n - 1].topic, cause_anchor(n)) +
                              " (" + std::to_string(count) + ")");
    md += "- **Known causes** that close part of the gap of the most claims that differ or hold in part: " + list + ".\n";
  }
  md += "\n**Where the text holds, by chapter:**\n\n" + chapter_story_markdown(rows, grades);
  return md;
}

}  // namespace capsule::analysis
