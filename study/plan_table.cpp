#include "study/plan_table.hpp"

#include <cstdio>
#include <iomanip>
#include <map>

#include "study/expansion.hpp"
#include "study/member_state.hpp"

#include "study/cost_estimate.hpp"

namespace capsule::study {

namespace {
std::string format_number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}
}  // namespace

void print_plan(const Campaign& campaign, const ResultsLayout& layout, std::ostream& out) {
  out << "campaign " << campaign.name;
  if (!campaign.description.empty()) out << ": " << campaign.description;
  out << "\nresults: " << layout.root.string() << "\n";
  out << std::left << std::setw(5) << "#" << std::setw(12) << "state" << std::setw(4) << "dim" << std::setw(12)
      << "nodes" << std::setw(14) << "kt" << std::setw(14) << "node-steps"
      << "member (parameters)\n";
  double total_node_steps = 0;
  double total_node_kt = 0;
  std::size_t members = 0;
  std::map<MemberState, std::size_t> counts;
  for_each_member(
      campaign,
      [&](Member&& m) {
        const std::size_t i = members++;
        const MemberCondition condition = inspect_member(layout.member(m), m.id);
        ++counts[condition.state];
        const CostEstimate c = estimate_cost(m.scene);
        const bool pending = condition.state != MemberState::complete;
        const std::string node_steps = format_number(c.node_steps());
        if (pending) total_node_steps += c.node_steps();
        if (pending) total_node_kt += static_cast<double>(c.nodes) * c.kt_span;
        std::string params;
        for (const auto& [key, value] : m.parameters) params += (params.empty() ? "" : ", ") + key + "=" + value.dump();
        out << std::left << std::setw(5) << i << std::setw(12) << state_name(condition.state) << std::setw(4)
            << m.scene.at("dim").get<int>() << std::setw(12) << c.nodes << std::setw(14)
            << ((c.kt_is_bound ? "<=" : "") + format_number(c.kt_span)) << std::setw(14) << node_steps
            << m.dir_name();
        if (!m.case_name.empty() || !params.empty())
          out << " (" << (m.case_name.empty() ? "" : "case " + m.case_name + (params.empty() ? "" : "; ")) << params
              << ")";
        if (!condition.reason.empty()) out << "  -- " << condition.reason;
        out << "\n";
      },
      [&](std::size_t index, const std::string& case_name) {
        out << "     (case " << case_name << " has the scene of member " << index << ")\n";
      });
  out << members << " members: " << counts[MemberState::complete] << " complete, " << counts[MemberState::fresh]
      << " new, " << counts[MemberState::interrupted] << " interrupted, " << counts[MemberState::failed]
      << " failed, " << counts[MemberState::unstable] << " unstable, " << counts[MemberState::stopped]
      << " stopped\n";
  out << "cost of what is not complete: " << format_number(total_node_kt) << " node-kt";
  if (total_node_steps > 0) out << ", " << format_number(total_node_steps) << " node-steps";
  out << "\n";
}

}  // namespace capsule::study
