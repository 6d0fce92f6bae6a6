#include "study/plan/plan_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <map>
#include <optional>
#include <set>

#include "study/campaign/expansion.hpp"
#include "study/state/member_state.hpp"

#include "solver/io/member_file.hpp"
#include "solver/scene/json_text.hpp"
#include "solver/scene/memory_estimate.hpp"
#include "study/plan/analysis_keys.hpp"
#include "study/plan/concurrency.hpp"
#include "study/plan/duration_text.hpp"
#include "study/state/campaign_owner.hpp"
#include "study/state/member_reuse.hpp"
#include "study/state/stray_folders.hpp"

namespace capsule::study {

namespace {

std::string format_number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

// What `capsule check` says of a member that needs more than this machine's physical memory
// (the same estimate, solver/scene/memory_estimate.hpp); "" when it fits.
std::string memory_note(const CostEstimate& c) {
  const double have = physical_memory_bytes();
  if (have <= 0 || c.memory_bytes <= have) return "";
  return "  -- needs about " + format_bytes(c.memory_bytes) + " of memory, more than this machine's " + format_bytes(have) +
         ": capsule check refuses it here (lower resolution.a or resolution.domain, or run it on a larger machine)";
}
}  // namespace

double estimated_member_seconds(const CostEstimate& cost, int dim, int threads, const MeasuredSpeed& speed) {
  return speed.for_dim(dim).seconds(cost, threads);
}

CampaignEstimate estimate_campaign(const CampaignSurvey& survey, const MeasuredSpeed& speed, int cores) {
  CampaignEstimate e;
  bool any_3d = false;
  for (std::size_t i = 0; i < survey.members.size(); ++i)
    if (needs_run(survey.conditions[i], false, false)) {
      ++e.pending;
      any_3d = any_3d || survey.members[i].scene.at("dim").get<int>() == 3;
    }
  if (e.pending == 0) return e;
  const Concurrency conc = choose_concurrency(cores, static_cast<int>(e.pending), any_3d, 0, 0);
  e.jobs = conc.jobs;
  e.threads = conc.threads;
  double longest = 0;
  for (std::size_t i = 0; i < survey.members.size(); ++i) {
    if (!needs_run(survey.conditions[i], false, false)) continue;
    const Member& m = survey.members[i];
    const double s = estimated_member_seconds(estimate_cost(m.scene, &speed.lengths), m.scene.at("dim").get<int>(), e.threads, speed);
    e.member_seconds += s;
    longest = std::max(longest, s);
  }
  // Members side by side: the sum spread over the jobs, and never less than the longest one.
  e.wall_seconds = std::max(longest, e.member_seconds / e.jobs);
  return e;
}

PlanSummary print_plan(const Campaign& plan_campaign, const ResultsLayout& layout, std::ostream& out,
                       const MemberSelection& selection) {
  PlanSummary summary;
  // Pass 1, member by member: the measured speeds of members that ran, and what is pending.
  MeasuredSpeed speed;
  speed.lengths = PhaseLengths::known(layout.root.parent_path());
  std::size_t pending_count = 0;
  bool any_3d = false;
  std::set<std::string> strays = member_folder_names(layout);  // emptied of the members' folders below
  const ReusableMembers elsewhere(layout.root.parent_path(), layout.root);
  // A member another campaign finished costs nothing: `study run` copies it (finished_elsewhere.hpp).
  const auto copyable = [&](const Member& m, const MemberCondition& c) -> std::optional<FinishedMember> {
    if (c.state != MemberState::fresh && c.state != MemberState::interrupted && c.state != MemberState::failed)
      return std::nullopt;
    return elsewhere.find(m);
  };
  // A large campaign is read twice (the cost first, then the table): say so, and how far the
  // first pass is, so a 10^6-member plan is never silent for the better part of a minute.
  std::size_t expected = 0;
  for (const auto& c : plan_campaign.cases) expected += (c.sweep ? *c.sweep : plan_campaign.sweep).count();
  if (plan_campaign.cases.empty()) expected = plan_campaign.sweep.count();
  constexpr std::size_t kProgressEvery = 100000;
  if (expected >= kProgressEvery)
    out << "planning about " << expected << " members: their state and cost first, then the table\n" << std::flush;
  std::size_t read = 0;
  std::vector<bool> matched(selection.where.size(), false);
  for_each_member(
      plan_campaign,
      [&](Member&& m) {
        if (++read % kProgressEvery == 0) out << "  read " << read << " of about " << expected << "\n" << std::flush;
        strays.erase(m.dir_name());
        if (read == 1) check_analysis_keys(plan_campaign, m.scene);
        const MemberCondition condition = inspect_member(layout.member(m), m.id);
        add_measurement(speed, m, layout.member(m));
        for (std::size_t c = 0; c < selection.where.size(); ++c)
          matched[c] = matched[c] || scene_matches(m.scene, {selection.where[c]});
        if (!selection.selects(m)) return;
        if (condition.state != MemberState::complete && !copyable(m, condition)) {
          ++pending_count;
          any_3d = any_3d || m.scene.at("dim").get<int>() == 3;
        }
      },
      [](std::size_t, const std::string&) {});
  require_matches(plan_campaign.source, selection, matched);
  CampaignEstimate campaign;
  campaign.pending = pending_count;
  if (pending_count > 0) {
    const Concurrency conc = choose_concurrency(usable_cores(), static_cast<int>(pending_count), any_3d, 0, 0);
    campaign.jobs = conc.jobs;
    campaign.threads = conc.threads;
  }
  out << "campaign " << plan_campaign.name;
  if (!plan_campaign.description.empty()) out << ": " << escape_controls(plan_campaign.description);
  out << "\nresults: " << layout.root.string() << "\n";
  out << std::left << std::setw(5) << "#" << std::setw(12) << "state" << std::setw(4) << "dim" << std::setw(12)
      << "nodes" << std::setw(14) << "kt" << std::setw(12) << "node-steps" << std::setw(10) << "seconds"
      << std::setw(10) << "memory"
      << "member (parameters)\n";
  double total_node_steps = 0;
  double total_node_kt = 0;
  double peak_memory = 0, longest = 0;
  std::size_t members = 0, copies = 0, index = 0;
  std::map<MemberState, std::size_t> counts;
  // Pass 2: one row per member, printed as it is expanded.
  for_each_member(
      plan_campaign,
      [&](Member&& m) {
        const std::size_t i = index++;  // the plan order of the whole campaign
        if (!selection.selects(m)) return;
        ++members;
        const MemberCondition condition = inspect_member(layout.member(m), m.id);
        ++counts[condition.state];
        const int dim = m.scene.at("dim").get<int>();
        const CostEstimate c = estimate_cost(m.scene, &speed.lengths);
        const std::optional<FinishedMember> copy_from = copyable(m, condition);
        if (copy_from) ++copies;
        const bool pending = condition.state != MemberState::complete && !copy_from;
        const std::string node_steps = format_number(c.node_steps());
        if (pending) total_node_steps += c.node_steps();
        if (pending) total_node_kt += static_cast<double>(c.nodes) * c.kt_span;
        if (pending) peak_memory = std::max(peak_memory, c.memory_bytes);
        // Seconds: what the member took when it has run, else the estimate ("~").
        std::string seconds;
        io::MemberStatus measured;
        if (!pending) {
          try {
            measured = io::read_member_status(layout.member(m).h5.string());
          } catch (const std::exception&) {
          }
        }
        if (pending) {
          const double estimate = estimated_member_seconds(c, dim, campaign.threads, speed);
          campaign.member_seconds += estimate;
          longest = std::max(longest, estimate);
          summary.pending_seconds[m.id] = estimate;
        }
        if (copy_from) seconds = "copy";
        else if (!pending && std::isfinite(measured.wall_seconds)) seconds = format_number(measured.wall_seconds);
        else {
          seconds = "~";  // append(): GCC 12 -O3 reports a false -Wrestrict on "literal" + string
          seconds.append(format_number(estimated_member_seconds(c, dim, pending ? campaign.threads : 1, speed)));
        }
        std::string params;
        for (const auto& [key, value] : m.parameters) params += (params.empty() ? "" : ", ") + key + "=" + value.dump();
        // The index never runs into the state: past 9999 members the column widens.
        out << std::left << std::setw(4) << i << ' ' << std::setw(12) << state_name(condition.state) << std::setw(4) << dim
            << std::setw(12) << c.nodes << std::setw(14) << ((c.kt_is_bound ? "<=" : "") + format_number(c.kt_span))
            << std::setw(12) << node_steps << std::setw(10) << seconds << std::setw(10) << format_bytes(c.memory_bytes)
            << m.dir_name();
        if (!m.case_name.empty() || !params.empty())
          out << " (" << (m.case_name.empty() ? "" : "case " + m.case_name + (params.empty() ? "" : "; ")) << params
              << ")";
        if (copy_from) out << "  -- finished in " << copy_from->campaign << ": `study run` copies it";
        else if (!condition.reason.empty()) out << "  -- " << condition.reason;
        if (pending) out << memory_note(c);
        out << "\n";
      },
      [&](std::size_t member_index, const std::string& case_name) {
        if (selection.everything()) out << "     (case " << case_name << " has the scene of member " << member_index << ")\n";
      });
  // Members side by side: the sum spread over the jobs, and never less than the longest one.
  if (campaign.pending > 0) campaign.wall_seconds = std::max(longest, campaign.member_seconds / campaign.jobs);
  out << members << " members: " << counts[MemberState::complete] << " complete, " << counts[MemberState::fresh]
      << " new, " << counts[MemberState::running] << " running, " << counts[MemberState::interrupted]
      << " interrupted, " << counts[MemberState::failed] << " failed, " << counts[MemberState::unstable]
      << " unstable, " << counts[MemberState::stopped] << " stopped";
  if (counts[MemberState::unreadable] > 0) out << ", " << counts[MemberState::unreadable] << " unreadable";
  if (!selection.everything()) out << " (the " << members << " of " << index << " that --case / --where select)";
  out << "\n";
  if (copies > 0)
    out << copies << " of them finished in other campaigns under " << layout.root.parent_path().string()
        << " (same scene and physics version): `study run` copies " << (copies > 1 ? "them" : "it")
        << " instead of running (--no-reuse runs " << (copies > 1 ? "them" : "it") << ")\n";
  out << describe_stray_folders(strays);
  out << "cost of what is not complete: " << format_number(total_node_kt) << " node-kt";
  if (total_node_steps > 0) out << ", " << format_number(total_node_steps) << " node-steps";
  out << "\n";
  if (campaign.pending > 0) {
    out << "estimated wall time: " << format_duration(campaign.wall_seconds) << " (" << format_number(campaign.wall_seconds)
        << " s) for " << campaign.pending << " members, " << campaign.jobs << " at once x " << campaign.threads
        << " thread" << (campaign.threads > 1 ? "s" : "") << "; largest member needs " << format_bytes(peak_memory)
        << " of memory (this machine has " << format_bytes(physical_memory_bytes()) << ")\n";
    for (int dim : {2, 3}) {
      const SpeedCalibration& k = speed.for_dim(dim);
      if (k.members > 0)
        out << "  " << dim << "D cost model corrected by x" << format_number(k.factor) << " from the measured speed of "
            << k.members << " member" << (k.members > 1 ? "s" : "") << " that ran\n";
      if (k.length_members > 0)
        out << "  " << dim << "D phases that end on a condition counted x" << format_number(k.length_factor)
            << " their model length, as " << k.length_members << " member" << (k.length_members > 1 ? "s" : "")
            << " that ran took\n";
    }
    out << "  (seconds: '~' estimated from the cost model, docs/guide/running.md \"Time and memory estimates\"; a phase that ends on a\n"
           "   condition counts at its expected end, a theta/beta stop at its cap)\n";
  }
  summary.jobs = campaign.jobs;
  summary.threads = campaign.threads;
  summary.wall_seconds = campaign.wall_seconds;
  summary.peak_memory = peak_memory;
  return summary;
}

void print_plans(const std::vector<std::string>& campaign_files, const std::filesystem::path& results_dir,
                 std::ostream& out) {
  std::map<std::string, double> once;  // member id -> seconds, the first campaign that runs it
  double wall = 0, peak = 0, core_seconds = 0;
  std::size_t pending = 0;
  for (const auto& file : campaign_files) {
    const Campaign campaign = load_campaign(file);
    const ResultsLayout layout(results_dir, campaign.name);
    require_same_campaign(campaign, layout);
    out << "\n== " << file << "\n";
    const PlanSummary s = print_plan(campaign, layout, out);
    double own = 0, fresh = 0;
    for (const auto& [id, seconds] : s.pending_seconds) {
      own += seconds;
      ++pending;
      if (once.emplace(id, seconds).second) {
        fresh += seconds;
        core_seconds += seconds * s.threads;
      }
    }
    // Its wall time without the members an earlier campaign of the list runs (this one copies them).
    if (own > 0) wall += s.wall_seconds * fresh / own;
    if (!s.pending_seconds.empty()) peak = std::max(peak, s.peak_memory);
  }
  out << "\n== all " << campaign_files.size() << " campaigns: " << pending << " members to run, " << once.size()
      << " of them different (" << pending - once.size()
      << " shared between campaigns run once, then copied); about " << format_number(core_seconds / 3600.0)
      << " core-hours, estimated wall time " << format_duration(wall) << " on this machine run one campaign after "
      << "another in this order; the largest member needs " << format_bytes(peak) << " of memory\n";
}

}  // namespace capsule::study
