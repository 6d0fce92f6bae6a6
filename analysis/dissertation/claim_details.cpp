#include "analysis/dissertation/claim_details.hpp"

#include "analysis/dissertation/deviations.hpp"
#include "analysis/dissertation/document_links.hpp"
#include "analysis/dissertation/figure_index.hpp"

namespace capsule::analysis {

std::string claim_details_markdown(const std::vector<ClaimResult>& rows, const std::string& results_dir,
                                   const std::string& link_base, const std::vector<CauseGrade>& grades) {
  std::string md;
  const auto verdicts = claim_verdicts(rows);
  std::size_t at = 0;  // rows of one claim are adjacent, in the order of claim_verdicts
  for (const auto& [key, verdict] : verdicts) {
    md += "#### <a id=\"" + claim_anchor(key) + "\"></a>" + key + " (Sec. " + rows[at].section + "): " +
          claim_verdict_text(verdict) + "\n\n";
    for (; at < rows.size() && rows[at].key == key; ++at) {
      const ClaimResult& r = rows[at];
      md += "- **The text:** " + r.statement + ". **Tested by:** " + r.campaign + ". **Criterion:** " + r.criterion +
            ".\n  **Verdict:** " + verdict_text(r.verdict) + ". **The toolkit measures:** " + r.measured + ".\n";
      if (!r.coarse_measured.empty())
        md += "  **Levels:** " + std::string(levels_text(r.levels)) + (r.levels == Levels::not_judged ? "not judged at the finest level" : "") +
              "; the next coarser level: " + r.coarse_measured + ".\n";
      else
        md += "  **Levels:** one level (no campaign it reads ships a point at two levels).\n";
      md += "  **The text passes its rule:** " + std::string(text_passes_text(r.text_passes)) +
            (r.text_numbers.empty() ? std::string(" (the text prints no numbers this rule can run on)") : " (" + r.text_numbers + ")") + ".\n";
      if (!r.reread.empty()) md += "  **Re-read:** " + r.reread + "\n";
    }
    for (const TextFigure* f : figures_of_claim(key))
      md += "- **Fig. " + f->number + "** (" + f->shows + "): " + figure_links(*f, results_dir, link_base) + ".\n";
    bool explained = false;
    for (const CauseGrade* g : grades_of_claim(grades, key)) {
      md += "- **Known cause** " + anchor_link(cause_label(g->cause) + " " + known_deviations()[g->cause - 1].topic, cause_anchor(g->cause)) +
            ": " + grade_sentence(*g) + ".\n";
      explained = explained || explains(*g);
    }
    if ((verdict == ClaimVerdict::differs || verdict == ClaimVerdict::in_part) && !explained)
      md += "- **Cause:** unexplained (no shipped probe measures a cause that closes a tenth of its gap or more).\n";
    md += "\n";
  }
  return md;
}

}  // namespace capsule::analysis
