#include "study/plan_table.hpp"

#include <cstdio>
#include <iomanip>

#include "study/cost_estimate.hpp"

namespace capsule::study {

namespace {
std::string format_number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}
}  // namespace

void print_plan(const CampaignSurvey& survey, std::ostream& out) {
  out << "campaign " << survey.campaign.name;
  if (!survey.campaign.description.empty()) out << ": " << survey.campaign.description;
  out << "\nresults: " << survey.layout.root.string() << "\n";
  out << std::left << std::setw(5) << "#" << std::setw(12) << "state" << std::setw(4) << "dim" << std::setw(12)
      << "nodes" << std::setw(14) << "kt" << std::setw(14) << "node-steps"
      << "member (parameters)\n";
  double total_node_steps = 0;
  double total_node_kt = 0;
  for (std::size_t i = 0; i < survey.members.size(); ++i) {
    const Member& m = survey.members[i];
    const CostEstimate c = estimate_cost(m.scene);
    const bool pending = survey.conditions[i].state != MemberState::complete;
    const std::string node_steps = format_number(c.node_steps());
    if (pending) total_node_steps += c.node_steps();
    if (pending) total_node_kt += static_cast<double>(c.nodes) * c.kt_span;
    std::string params;
    for (const auto& [key, value] : m.parameters) params += (params.empty() ? "" : ", ") + key + "=" + value.dump();
    out << std::left << std::setw(5) << i << std::setw(12) << state_name(survey.conditions[i].state) << std::setw(4)
        << m.scene.at("dim").get<int>() << std::setw(12) << c.nodes << std::setw(14)
        << ((c.kt_is_bound ? "<=" : "") + format_number(c.kt_span)) << std::setw(14) << node_steps << m.dir_name();
    std::string cases = m.case_name;
    for (const auto& other : m.other_cases) cases += ", " + other;
    if (!cases.empty() || !params.empty())
      out << " (" << (cases.empty() ? "" : "case " + cases + (params.empty() ? "" : "; ")) << params << ")";
    if (!survey.conditions[i].reason.empty()) out << "  -- " << survey.conditions[i].reason;
    out << "\n";
  }
  out << survey.members.size() << " members: " << survey.count(MemberState::complete) << " complete, "
      << survey.count(MemberState::fresh) << " new, " << survey.count(MemberState::interrupted) << " interrupted, "
      << survey.count(MemberState::failed) << " failed, " << survey.count(MemberState::unstable) << " unstable, "
      << survey.count(MemberState::stopped) << " stopped\n";
  out << "cost of what is not complete: " << format_number(total_node_kt) << " node-kt";
  if (total_node_steps > 0) out << ", " << format_number(total_node_steps) << " node-steps";
  out << "\n";
}

}  // namespace capsule::study
