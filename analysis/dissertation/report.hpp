#pragma once
// results/THESIS.md: the dissertation's Table 2, its ratios b/a and the claims of Chapters
// 2-5 beside what the shipped campaigns measure, and the known causes of disagreement. Its
// first screen is the bottom line (bottom_line.hpp) and one short table per chapter
// (chapter_tables.hpp); the figures (figure_index.hpp), Table 2, the claims in detail
// (claim_details.hpp) and the known causes follow.
// Regenerated from results/<campaign>/report/fits.json and member files only; a campaign
// not yet run gives "cannot tell", never an error.
#include <string>
#include <vector>

#include "analysis/dissertation/claims.hpp"
#include "analysis/dissertation/table2.hpp"

namespace capsule::analysis {

// Every campaign THESIS.md reads, in the order of the text.
const std::vector<std::string>& dissertation_campaigns();

struct DissertationSummary {
  std::string file;  // where THESIS.md was written ("" from dissertation_markdown)
  int agrees = 0, differs = 0, cannot_tell = 0;     // claim rows (a claim of both the circle and the sphere: two)
  int claims_agree = 0, claims_differ = 0, claims_in_part = 0, claims_cannot_tell = 0;  // claims (claim_verdicts)
  int coefficients_overlap = 0, coefficients_disjoint = 0, coefficients_unknown = 0;  // Table 2's 18
  // Richardson-extrapolated over the ladder (coefficients that have one): the difference test against
  // the text's, and whether the finest level moved toward the text from the next coarser
  int coefficients_extrapolated_pass = 0, coefficients_extrapolated_fail = 0;
  int coefficients_toward = 0, coefficients_away = 0;
  int linked_figures = 0;  // the toolkit's figures THESIS.md links (figure_index.hpp), all shipped
  int rows_converged = 0, rows_not_converged = 0, rows_one_level = 0, rows_not_judged = 0;  // claim rows (Levels)
  int text_passes = 0, text_fails = 0, text_no_numbers = 0;  // claims whose rule the text's own numbers pass (claim_text_passes)
  // Claims that differ, run again at the text's settings (emulation.hpp): the text's numbers come
  // back; still differ; cannot tell; the emulation campaign not shipped
  int emulation_text_numerics = 0, emulation_model = 0, emulation_cannot_tell = 0, emulation_not_run = 0;
};

// The document; `results_label` is how it names the results folder (as given on the command line),
// `link_base` the path from the document's folder to the results folder (its figure links).
std::string dissertation_markdown(const DissertationResults& results, const std::string& results_label,
                                  DissertationSummary* summary = nullptr, const std::string& link_base = ".");

// Writes `out_file` (parent folders created). Throws std::runtime_error when it cannot.
DissertationSummary write_dissertation(const std::string& results_dir, const std::string& out_file);

}  // namespace capsule::analysis
