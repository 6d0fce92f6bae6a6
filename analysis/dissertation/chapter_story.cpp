#include "analysis/dissertation/chapter_story.hpp"

#include <map>
#include <set>

#include "analysis/dissertation/chapter_tables.hpp"
#include "analysis/dissertation/cause_grades.hpp"
#include "analysis/dissertation/deviations.hpp"
#include "analysis/dissertation/document_links.hpp"

namespace capsule::analysis {

namespace {

// "3.2 modest, 3.3 slight and 2 more": keys linked while the line stays within `room` bytes.
std::string linked_keys(const std::vector<std::string>& keys, std::size_t room) {
  std::string list;
  std::size_t shown = 0;
  for (const auto& key : keys) {
    const std::string link = anchor_link(key, claim_anchor(key));
    const std::size_t rest = keys.size() - shown - 1;
    const std::string tail = rest ? " and " + std::to_string(rest) + " more" : "";
    if (list.size() + link.size() + 2 + tail.size() > room && shown > 0) break;
    append_listed(list, link);
    ++shown;
  }
  if (shown < keys.size()) list += " and " + std::to_string(keys.size() - shown) + " more";
  return list;
}

std::string plural(std::size_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}


// " Of those that differ: 2 with a measured cause closing part of the gap (the most: C12 Fluid
// spin-down closes 35 % of 3.1 R2's), 5 unexplained: ..." for the claims that differ or hold in part.
std::string causes_sentence(const std::vector<std::string>& differing, const std::vector<CauseGrade>& grades, std::size_t used) {
  if (differing.empty()) return "";
  std::vector<std::string> unexplained;
  std::size_t explained = 0;
  const CauseGrade* best = nullptr;
  std::set<std::size_t> not_closing;  // causes measured on these claims that close less than a tenth of the gap
  for (const auto& key : differing) {
    bool any = false;
    for (const CauseGrade* g : grades_of_claim(grades, key)) {
      if (g->measured && !explains(*g)) not_closing.insert(g->cause);
      if (!explains(*g)) continue;
      any = true;
      if (!best || g->fraction > best->fraction) best = g;
    }
    if (any) ++explained;
    else unexplained.push_back(key);
  }
  std::string s = " Of those that differ: " + std::to_string(explained) + " with a measured cause closing part of the gap";
  if (best)
    s += " (the most: " + anchor_link(cause_label(best->cause), cause_anchor(best->cause)) + " " +
         known_deviations()[best->cause - 1].topic + " " + closes_text(*best) + " of " +
         anchor_link(best->gap.claim, claim_anchor(best->gap.claim)) + ")";
  if (unexplained.empty()) return s + ".";
  s += ", " + std::to_string(unexplained.size()) + " unexplained";
  if (!not_closing.empty()) {
    std::string causes;
    for (const std::size_t n : not_closing) append_listed(causes, anchor_link(cause_label(n), cause_anchor(n)));
    s += " (" + causes + " measured: " + (not_closing.size() == 1 ? "it widens or barely moves" : "they widen or barely move") + " the gap)";
  }
  s += ": ";
  const std::size_t room = k_prose_line_characters > used + s.size() + 2 ? k_prose_line_characters - used - s.size() - 2 : 0;
  return s + linked_keys(unexplained, room) + ".";
}

}  // namespace

std::string chapter_story_markdown(const std::vector<ClaimResult>& rows, const std::vector<CauseGrade>& grades) {
  std::map<std::string, std::string> chapter_of;
  for (const auto& r : rows) chapter_of.emplace(r.key, claim_chapter(r));
  std::string md;
  for (const auto& chapter : text_chapters()) {
    std::map<ClaimVerdict, std::vector<std::string>> keys;
    std::size_t total = 0;
    for (const auto& [key, v] : claim_verdicts(rows)) {
      if (chapter_of[key] != chapter.number) continue;
      ++total;
      keys[v].push_back(key);
    }
    if (total == 0) continue;
    std::vector<std::string> differing = keys[ClaimVerdict::differs];
    differing.insert(differing.end(), keys[ClaimVerdict::in_part].begin(), keys[ClaimVerdict::in_part].end());
    std::string line = "- **Ch. " + chapter.number + "**: the text holds in " + std::to_string(keys[ClaimVerdict::agrees].size()) +
                       " of its " + plural(total, "claim", "claims") + " here; it does not in " +
                       std::to_string(keys[ClaimVerdict::differs].size()) +
                       (keys[ClaimVerdict::in_part].empty() ? "" : " (and in part in " + std::to_string(keys[ClaimVerdict::in_part].size()) + ")") +
                       (keys[ClaimVerdict::cannot_tell].empty() ? "" : "; " + std::to_string(keys[ClaimVerdict::cannot_tell].size()) + " cannot tell") + ".";
    md += line + causes_sentence(differing, grades, line.size()) + "\n";
  }
  return md;
}

}  // namespace capsule::analysis
