#include "solver/common/atomic_write.hpp"
#include "analysis/dissertation/report.hpp"

#include "analysis/dissertation/prose_lines.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "analysis/dissertation/bottom_line.hpp"
#include "analysis/dissertation/cause_grades.hpp"
#include "analysis/dissertation/chapter_tables.hpp"
#include "analysis/dissertation/claim_details.hpp"
#include "analysis/dissertation/deviations.hpp"
#include "analysis/dissertation/document_links.hpp"
#include "analysis/dissertation/emulation.hpp"
#include "analysis/dissertation/figure_axes.hpp"
#include "analysis/dissertation/figure_index.hpp"
#include "analysis/dissertation/validation.hpp"

namespace capsule::analysis {

namespace fs = std::filesystem;

const std::vector<std::string>& dissertation_campaigns() {
  static const std::vector<std::string> c = {
      "ch2_3d_visco", "ch3_ca", "ch3_eb", "ch3_v", "ch3_eta", "ch4_2d_tt", "ch4_2d_tumble", "ch4_3d_cases",
      "ch5_bilinear_ca005", "ch5_bilinear_ca005_eb", "ch5_bilinear_ca02", "ch5_powerlaw", "ch5_oscillatory"};
  return c;
}

namespace {

// Which figures the reports draw as the text does, several members on one plot.
std::string overlaid_figures_sentence() {
  std::string together;
  for (const auto& a : figure_axes())
    if (!a.together.empty()) append_listed(together, a.number);
  if (together.empty()) return "The toolkit draws one panel per member where the text overlays several.";
  return "Where the text overlays several members, the toolkit does too for Figs. " + together +
         " (fig<N>.png) and draws one panel per member for the others.";
}

Table campaign_table(const DissertationResults& results) {
  Table t;
  t.title = "Campaigns read";
  t.header = {"campaign", "fits.json", "members in it", "complete", "member files found",
              "ladder levels judged (finest shipped per point)"};
  std::vector<std::string> names = validation_campaigns();
  names.insert(names.end(), dissertation_campaigns().begin(), dissertation_campaigns().end());
  for (const auto& name : names) {
    const DissertationCampaign& c = results.campaign(name);
    if (!c.found) {
      t.rows.push_back({name, "not run", "", "", "", ""});
      continue;
    }
    const auto members = c.in_case_all_levels("");
    int complete = 0, files = 0;
    for (const auto* m : members) {
      complete += m->status == "complete";
      files += !m->file.empty();
    }
    t.rows.push_back({name, "yes", std::to_string(members.size()), std::to_string(complete), std::to_string(files),
                      c.judged_levels()});
  }
  return t;
}

// The Table 2 coefficients counted: overlapping, disjoint, unknown; extrapolated pass / fail and
// moving toward / away from the text.
void count_table2(const std::vector<Table2RowComparison>& rows, DissertationSummary& s) {
  for (const auto& row : rows) {
    if (!row.found) {
      s.coefficients_unknown += 3;
      continue;
    }
    for (const auto& c : row.coefficients) {
      if (!c.measured) ++s.coefficients_unknown;
      else if (c.overlap) ++s.coefficients_overlap;
      else ++s.coefficients_disjoint;
      if (const auto x = extrapolated_difference_test(row, c)) {
        ++(x->passes ? s.coefficients_extrapolated_pass : s.coefficients_extrapolated_fail);
        if (x->moves != 0) ++(x->moves > 0 ? s.coefficients_toward : s.coefficients_away);
      }
    }
  }
}

// The claim rows counted by verdict and convergence, the claims by verdict and by whether the text
// passes its own rule.
void count_claims(const std::vector<ClaimResult>& claims, DissertationSummary& s) {
  for (const auto& c : claims) {
    ++(c.levels == Levels::converged       ? s.rows_converged
       : c.levels == Levels::not_converged ? s.rows_not_converged
       : c.levels == Levels::one_level     ? s.rows_one_level
                                           : s.rows_not_judged);
    if (c.verdict == Verdict::agrees) ++s.agrees;
    else if (c.verdict == Verdict::differs) ++s.differs;
    else ++s.cannot_tell;
  }
  for (const auto& [key, v] : claim_verdicts(claims))
    ++(v == ClaimVerdict::agrees    ? s.claims_agree
       : v == ClaimVerdict::differs ? s.claims_differ
       : v == ClaimVerdict::in_part ? s.claims_in_part
                                    : s.claims_cannot_tell);
  for (const auto& [key, t] : claim_text_passes(claims))
    ++(t == TextPasses::yes ? s.text_passes : t == TextPasses::no ? s.text_fails : s.text_no_numbers);
}

// The title, the bottom line and the chapter tables with the words they use.
std::string opening_markdown(const std::vector<ClaimResult>& claims, const std::vector<CauseGrade>& grades, const DissertationSummary& s,
                             const std::string& results_label, const std::string& emulation_line) {
  std::string md;
  md += "# The dissertation beside this toolkit\n\n";
  md += "\"Modeling and Simulation of Shape Changes of Red Blood Cells in Shear Flow\" (ODU 2014) against the "
        "shipped results of this toolkit; generated by `study thesis --results " + results_label +
        "` (do not edit by hand). Times are k tau (shear-rate units).\n\n";
  md += bottom_line_markdown(claims, s, grades) + "\n";
  md += emulation_line + "\n\n";
  md += "## Claims by chapter\n\n";
  md += "One row per claim (two where the text makes it for the circle and the sphere): the claim links to its "
        "detail section (full criterion, numbers, members, figures); a cell cut short ends in \"…\". *agrees*: the "
        "criterion holds; *differs*: it does not; *cannot tell*: what it needs is missing. text passes: the same "
        "rule run on the text's own numbers (its Table 2, the numbers in its sentences): *yes*, *no*, or *no numbers* "
        "where the text prints none the rule can run on (its figures are not digitised). cause: the "
        "[known causes](#known-causes) linked from the claim, each with the share of the gap between the toolkit and the text "
        "it closes as a shipped probe measures it, (with the cause - toolkit)/(text - toolkit); *unexplained*: the claim differs "
        "and no measured cause closes a tenth of its gap or more.\n\n";
  md += chapter_tables_markdown(claims, grades);
  md += "### Words used here\n\n"
        "- **campaign**: a set of simulations run together for one figure or table of the text (`campaigns/dissertation/<name>.json`); "
        "its results are in `<name>/report/`.\n"
        "- **member**: one simulation of a campaign, one physical point at one resolution; its file `member.h5` records the "
        "D_xy, theta, tension and shear-rate series over time and the markers D_max, D_stop, t_stop.\n"
        "- **ladder**, **level**: the same physical point run at several resolutions (`resolution.a`: lattice units per capsule "
        "radius, 5 and 7; `resolution.mesh_level`: the 3D mesh's refinement); the finest level is the largest a.\n"
        "- **converged**, **not converged**, **one level**: the verdict at the two finest levels of the ladder is the same; "
        "differs between them (the claim cannot tell); the campaign ships one level only.\n"
        "- **text passes**: the claim's rule run on the text's own printed numbers (Table 2, numbers in its sentences).\n"
        "- **k tau_s**, **k tau_r**: response and recovery times (85), (86) in shear-rate units; **k tau_R1**, **k tau_R2**: "
        "the fast and slow recovery times of (88)-(90); **w_R1**: the share of the recovery carried by the fast phase when "
        "the two amplitudes of (90) are fitted freely (**free amplitudes**; (90) fixes it at 1/2).\n"
        "- **C1 ... C" + std::to_string(known_deviations().size()) + "**: the known causes of disagreement (below); a cause is linked from a claim only "
        "where a shipped probe measures how much of the claim's gap it closes; a claim that differs with no cause closing a tenth of its gap or more is "
        "*unexplained*.\n\n";
  return md;
}

std::string figures_section_markdown(const DissertationResults& results, const DissertationSummary& s, const std::string& link_base) {
  std::string md;
  md += "## Figures\n\n";
  md += "The dissertation's figures that a shipped campaign's report regenerates with the same axes and quantities "
        "(" + std::to_string(s.linked_figures) + " toolkit figures linked; the table is "
        "analysis/dissertation/figures.md; each figure's axes, those of the text's caption, are in "
        "analysis/dissertation/figure_axes.md). " + overlaid_figures_sentence() + "\n\n";
  md += figures_markdown(results.results_dir(), link_base) + "\n";
  return md;
}

// The counts of the summary; `claims` and `rows` the numbers of claims and of claim rows.
std::string summary_markdown(const DissertationSummary& s, std::size_t claims, std::size_t rows) {
  std::string md;
  md += "## Summary\n\n";
  md += "Generated from the shipped campaign results (`<campaign>/report/fits.json` and the member files it names). "
        "A campaign not yet run, or a member whose fit or file is missing, gives *cannot tell* with what is missing, "
        "never a guess. In a campaign with a resolution ladder every claim is judged twice: each physical point (and "
        "each bilinear fit) at its finest shipped level (the last column of \"Campaigns read\"), and at the next coarser "
        "level where the point has one; a verdict stands only where both give it (*converged*), otherwise the claim "
        "cannot tell (*not converged*, both levels' numbers given). A campaign shipped at one level says so (*one level*).\n\n";
  md += "- Claims: " + std::to_string(s.claims_agree) + " agree, " + std::to_string(s.claims_differ) + " differ, " +
        std::to_string(s.claims_in_part) + " hold in part, " + std::to_string(s.claims_cannot_tell) + " cannot tell (of " +
        std::to_string(claims) + " claims; in part: the rows of one claim, such as its circle and its sphere, "
        "disagree, or some cannot tell).\n";
  md += "- Rows of the claims table: " + std::to_string(s.agrees) + " agree, " + std::to_string(s.differs) + " differ, " +
        std::to_string(s.cannot_tell) + " cannot tell (of " + std::to_string(rows) + ").\n";
  md += "- Convergence of the rows: " + std::to_string(s.rows_converged) + " converged (the same verdict at the two finest "
        "levels), " + std::to_string(s.rows_not_converged) + " not converged (cannot tell), " + std::to_string(s.rows_one_level) +
        " on campaigns shipped at one level, " + std::to_string(s.rows_not_judged) + " not judged at the finest level.\n";
  md += "- The text passes its own rule: " + std::to_string(s.text_passes) + " yes, " + std::to_string(s.text_fails) +
        " no, " + std::to_string(s.text_no_numbers) + " no numbers (of " + std::to_string(claims) + " claims).\n";
  md += "- Table 2 coefficients, statistical 95 % intervals only: " + std::to_string(s.coefficients_overlap) +
        " overlap, " + std::to_string(s.coefficients_disjoint) + " do not, " + std::to_string(s.coefficients_unknown) +
        " cannot tell (of 18).\n";
  md += "- Table 2 coefficients Richardson-extrapolated over the ladder against the text's: " +
        std::to_string(s.coefficients_extrapolated_pass) + " pass the difference test (|extrapolated - text| <= 1.96 "
        "combined sigma), " + std::to_string(s.coefficients_extrapolated_fail) + " do not (of the " +
        std::to_string(s.coefficients_extrapolated_pass + s.coefficients_extrapolated_fail) + " with an extrapolation); from the "
        "next coarser level to the finest " + std::to_string(s.coefficients_toward) + " move toward the text, " +
        std::to_string(s.coefficients_away) + " away.\n\n";
  return md;
}

// The validation, Table 2 and ratio sections: each its title, what it shows, and its table.
std::string tables_markdown(const DissertationResults& results, const std::vector<Table2RowComparison>& rows) {
  std::string md;
  const auto section = [&md](const std::string& title, const std::string& intro, const Table& table) {
    md += "## " + title + "\n\n" + intro + "\n\n" + table.to_markdown() + "\n";
  };
  section("Validation against published curves (Ch. 2, Fig. 7)",
          "The text compares its 3D solver with Ramanujan and Pozrikidis (1998) and finds \"excellent agreement\" for "
          "the neo-Hookean sphere at V = 1 (Fig. 7; Sec. 2). The toolkit's members at the campaign's resolution "
          "against the same digitised curves (digitising error about +-0.005 in D); D_xy is the inertia-ellipsoid "
          "measure (38), D_extent the extent measure of the paper. The toolkit's excess falls with resolution "
          "(solver/membrane3d/README.md \"Validation\"; \"Resolution and the immersed boundary\" below): a "
          "resolution error of the immersed boundary, which the text's a = 10 shares.",
          validation_table(results));
  section("Table 2 (Sec. 5.1.1)",
          "Each row of the dissertation's Table 2 beside the bilinear fit (95)-(96) of the campaign that regenerates "
          "it; overlap: the two 95 % intervals share a point. The text gives R^2 > 0.99 for every k tau_r fit and "
          "about 0.91 / 0.96 / 0.95 for k tau_s. The last three columns: the coefficient at the ladder's next coarser "
          "level (and whether the finest moved toward the text from it), the coefficient Richardson-extrapolated to "
          "zero spacing with its error estimate, and the difference test |extrapolated - text| <= 1.96 sigma, sigma^2 "
          "= (text half-width / 1.96)^2 + (fit half-width / 1.96)^2 + Richardson error^2.",
          table2_side_by_side(rows));
  section("Ratios b/a (Sec. 5.1.1)",
          "The text quotes b_s/a_s ~ 2.8, 3.5, 3.5 and b_r/a_r ~ 5, 4.6, 4.1. \"From Table 2\": b/a of the printed "
          "coefficients, its interval by the first-order delta method from their 95 % half-widths, a and b taken as "
          "independent (the text gives no covariance). The toolkit's interval uses the fit's covariance of a and b "
          "when fits.json carries it (delta method, times Student's t with N - 3 degrees of freedom), else the same "
          "half-width rule; the last column says which.",
          table2_ratios(rows));
  return md;
}

}  // namespace

std::string dissertation_markdown(const DissertationResults& results, const std::string& results_label,
                                  DissertationSummary* summary, const std::string& link_base) {
  DissertationSummary s;
  const auto rows = compare_table2_rows(results);
  count_table2(rows, s);
  const auto claims = evaluate_claims_at_two_levels(results);
  count_claims(claims, s);
  s.linked_figures = linked_figure_count(figure_index(), results.results_dir());

  // The third column: the same rules on the emulation campaigns (emulation.hpp).
  const DissertationResults emulated(results.results_dir(), 0, k_emulation_prefix);
  std::vector<std::string> shipped;
  for (const auto& name : dissertation_campaigns())
    if (emulated.campaign(name).found) shipped.push_back(name);
  auto emulation = emulation_rows(claims, evaluate_claims(emulated), shipped);
  for (const auto& sw : emulation_switches())
    attach_switch(emulation, evaluate_claims(DissertationResults(results.results_dir(), 0,
                                                                 std::string(k_emulation_prefix) + sw.label + "_")));
  const EmulationCounts emulation_counts = count_emulation(emulation);
  s.emulation_text_numerics = emulation_counts.text_numerics;
  s.emulation_model = emulation_counts.model;
  s.emulation_cannot_tell = emulation_counts.cannot_tell;
  s.emulation_not_run = emulation_counts.not_run;

  const auto grades = grade_causes(results);
  std::string md = opening_markdown(claims, grades, s, results_label, emulation_count_line(emulation_counts));
  md += figures_section_markdown(results, s, link_base);
  md += summary_markdown(s, claim_verdicts(claims).size(), claims.size());
  md += campaign_table(results).to_markdown() + "\n";
  md += tables_markdown(results, rows);
  md += emulation_section_markdown(emulation, rows, compare_table2_rows(emulated));
  md += "## Claims of Chapters 2-5\n\n";
  md += "Each claim in detail, the target of the chapter tables' links. Each claim of the text is a rule with a numeric criterion, judged from the fitted times (and, where it is "
        "about a curve, the member files) of the campaign named; the numbers say by how much it holds or fails.\n\n";
  md += claim_details_markdown(claims, results.results_dir(), link_base, grades);
  md += "<a id=\"known-causes\"></a>\n\n## Known causes of disagreement\n\n";
  md += "Where the toolkit departs from the text on purpose, or measures what the text does not control. Before "
        "reading a *differs* as an error of either, check whether one of these moves it.\n\n";
  md += known_deviations_markdown(results, grades);
  if (summary) *summary = s;
  return wrap_prose_lines(md);
}

DissertationSummary write_dissertation(const std::string& results_dir, const std::string& out_file) {
  const DissertationResults results(results_dir);
  DissertationSummary s;
  const fs::path out(out_file);
  const fs::path document_folder = fs::absolute(out).parent_path();
  const std::string link_base = fs::absolute(results_dir).lexically_normal().lexically_relative(document_folder.lexically_normal()).generic_string();
  const std::string md = dissertation_markdown(results, results_dir, &s, link_base.empty() ? "." : link_base);
  if (out.has_parent_path()) fs::create_directories(out.parent_path());
  capsule::write_file_atomically(out, md);
  s.file = out.string();
  return s;
}

}  // namespace capsule::analysis
