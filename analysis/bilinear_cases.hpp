#pragma once
// The bilinear model (95)-(96) fitted once per case and target over a report's members;
// shared by the bilinear table and the artificial-viscosity maps (97)-(98) built on it.
#include <string>
#include <vector>

#include "analysis/fit_result.hpp"
#include "analysis/report_context.hpp"

namespace capsule::analysis {

struct CaseBilinear {
  std::string case_name, target;
  std::vector<const MemberAnalysis*> group;  // every member of the case
  std::vector<double> eta, V, k_tau;         // the members fitted
  std::vector<std::string> used, excluded;   // slugs fitted; "<slug>: <why not>"
  FitResult fit;
};

// Case names in order of first appearance.
std::vector<std::string> case_names(const std::vector<MemberAnalysis>& members);

// One entry per case and target of the block's "bilinear" (none without it).
std::vector<CaseBilinear> bilinear_per_case(const ReportContext& context);

}  // namespace capsule::analysis
