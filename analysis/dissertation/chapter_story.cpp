#include "analysis/dissertation/chapter_story.hpp"

#include <map>

#include "analysis/dissertation/chapter_tables.hpp"
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

}  // namespace

std::string chapter_story_markdown(const std::vector<ClaimResult>& rows) {
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
    // Of the claims that differ or hold in part: those with a cause linked, counted per cause.
    std::vector<std::string> unexplained;
    std::map<std::size_t, int> per_cause;
    std::size_t with_cause = 0;
    for (const ClaimVerdict v : {ClaimVerdict::differs, ClaimVerdict::in_part})
      for (const auto& key : keys[v]) {
        const auto causes = causes_of_claim(key);
        if (causes.empty()) unexplained.push_back(key);
        else ++with_cause;
        for (const std::size_t n : causes) ++per_cause[n];
      }
    std::size_t top = 0;
    for (const auto& [n, count] : per_cause)
      if (!top || count > per_cause[top]) top = n;
    std::string line = "- **Ch. " + chapter.number + "**: the text holds in " + std::to_string(keys[ClaimVerdict::agrees].size()) +
                       " of its " + plural(total, "claim", "claims") + " here; it does not in " +
                       std::to_string(keys[ClaimVerdict::differs].size()) +
                       (keys[ClaimVerdict::in_part].empty() ? "" : " (and in part in " + std::to_string(keys[ClaimVerdict::in_part].size()) + ")") +
                       (keys[ClaimVerdict::cannot_tell].empty() ? "" : "; " + std::to_string(keys[ClaimVerdict::cannot_tell].size()) + " cannot tell") + ".";
    if (!per_cause.empty() || !unexplained.empty()) {
      line += " Of those that differ: " + std::to_string(with_cause) + " with a known cause linked";
      if (top) line += " (most often " + anchor_link(cause_label(top), cause_anchor(top)) + " " + known_deviations()[top - 1].topic + ")";
      line += unexplained.empty() ? std::string(".")
                                  : ", " + std::to_string(unexplained.size()) + " unexplained (no cause linked): ";
      if (!unexplained.empty()) {
        const std::size_t room = k_prose_line_characters > line.size() + 2 ? k_prose_line_characters - line.size() - 2 : 0;
        line += linked_keys(unexplained, room) + ".";
      }
    }
    md += line + "\n";
  }
  return md;
}

}  // namespace capsule::analysis
