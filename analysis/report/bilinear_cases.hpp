#pragma once
// The bilinear model (95)-(96) fitted once per case and target over a report's members;
// shared by the bilinear table and the artificial-viscosity maps (97)-(98) built on it.
#include <string>
#include <vector>

#include "analysis/fit/fit_result.hpp"
#include "analysis/report/report_context.hpp"
#include "analysis/fit/richardson.hpp"

namespace capsule::analysis {

struct CaseBilinear {
  std::string case_name, target;
  std::string level_key;                     // bilinear.ladder ("" without one)
  double level = 0.0;                        // the key's value these members share (with a ladder)
  std::vector<const MemberAnalysis*> group;  // every member of the case (at this level)
  std::vector<double> eta, V, k_tau;         // the members fitted
  std::vector<std::string> used, excluded;   // slugs fitted; "<slug>: <why not>"
  FitResult fit;
};

// Case names in order of first appearance.
std::vector<std::string> case_names(const std::vector<MemberAnalysis>& members);

// One entry per case and target of the block's "bilinear" (none without it); with
// bilinear.ladder, one per case, level and target, the finest level (smallest h) first.
// A member without a number at the ladder key is on no level: it is listed in `unplaced`.
std::vector<CaseBilinear> bilinear_per_case(const ReportContext& context,
                                            std::vector<std::string>* unplaced = nullptr);

// "a = 7" for an entry with a level, "" without.
std::string level_label(const CaseBilinear& b);

// One coefficient of one case and target over the ladder's levels (bilinear.ladder).
struct CoefficientLadder {
  std::string case_name, target, coefficient;   // coefficient: "a", "b" or "c"
  std::vector<std::pair<double, double>> levels; // (key value, coefficient), finest first
  std::vector<std::string> skipped;              // "a = 5: fit failed: ..."
  RichardsonResult result;
};

// Per case, target and coefficient (a, b, c): the extrapolation over the levels whose fit
// succeeded (none without a ladder).
std::vector<CoefficientLadder> bilinear_ladders(const ReportContext& context, const std::vector<CaseBilinear>& fits);

}  // namespace capsule::analysis
