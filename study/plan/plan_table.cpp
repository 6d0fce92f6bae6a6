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
#include "common/json_text.hpp"
#include "solver/scene/memory_estimate.hpp"
#include "study/plan/analysis_keys.hpp"
#include "study/plan/concurrency.hpp"
#include "study/state/duration_text.hpp"
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

// About how many members the campaign expands to (its cases' sweeps, or its own).
std::size_t expected_member_count(const Campaign& campaign) {
  std::size_t expected = 0;
  for (const auto& c : campaign.cases) expected += (c.sweep ? *c.sweep : campaign.sweep).count();
  if (campaign.cases.empty()) expected = campaign.sweep.count();
  return expected;
}

// The running totals of the table's rows.
struct PlanTotals {
  double node_steps = 0, node_kt = 0;  // of the pending members
  double peak_memory = 0, longest = 0;
  std::size_t members = 0, copies = 0, index = 0;
  std::map<MemberState, std::size_t> counts;
};

// One plan table, from two passes over the campaign's members (member by member: bounded
// memory): their states and the measured speeds first, then one row per member with its cost.
class PlanPrinter {
 public:
  PlanPrinter(const Campaign& campaign, const ResultsLayout& layout, const MemberSelection& selection, std::ostream& out)
      : campaign_(campaign), layout_(layout), selection_(selection), out_(out),
        elsewhere_(layout.root.parent_path(), layout.root) {}

  PlanSummary print() {
    read_states_and_speeds();
    print_header();
    // Pass 2: one row per member, printed as it is expanded.
    for_each_member(
        campaign_, [&](Member&& m) { print_row(m, totals_.index++); },
        [&](std::size_t member_index, const std::string& case_name) {
          if (selection_.everything())
            out_ << "     (case " << case_name << " has the scene of member " << member_index << ")\n";
        });
    // Members side by side: the sum spread over the jobs, and never less than the longest one.
    if (estimate_.pending > 0) estimate_.wall_seconds = std::max(totals_.longest, estimate_.member_seconds / estimate_.jobs);
    print_counts();
    print_cost();
    summary_.jobs = estimate_.jobs;
    summary_.threads = estimate_.threads;
    summary_.wall_seconds = estimate_.wall_seconds;
    summary_.peak_memory = totals_.peak_memory;
    return summary_;
  }

 private:
  // A member another campaign finished costs nothing: `study run` copies it (member_reuse.hpp).
  std::optional<FinishedMember> copy_source(const Member& m, const MemberCondition& c) const {
    if (c.state != MemberState::fresh && c.state != MemberState::interrupted && c.state != MemberState::failed)
      return std::nullopt;
    return elsewhere_.find(m);
  }

  // Pass 1, member by member: the measured speeds of members that ran, and what is pending.
  void read_states_and_speeds() {
    speed_.lengths = PhaseLengths::known(layout_.root.parent_path());
    strays_ = member_folder_names(layout_);  // emptied of the members' folders below
    // A large campaign is read twice (the cost first, then the table): say so, and how far the
    // first pass is, so a 10^6-member plan is never silent for the better part of a minute.
    const std::size_t expected = expected_member_count(campaign_);
    constexpr std::size_t kProgressEvery = 100000;
    if (expected >= kProgressEvery)
      out_ << "planning about " << expected << " members: their state and cost first, then the table\n" << std::flush;
    std::size_t read = 0, pending = 0;
    bool any_3d = false;
    std::vector<bool> matched(selection_.where.size(), false);
    for_each_member(
        campaign_,
        [&](Member&& m) {
          if (++read % kProgressEvery == 0) out_ << "  read " << read << " of about " << expected << "\n" << std::flush;
          strays_.erase(m.dir_name());
          if (read == 1) check_analysis_keys(campaign_, m.scene);
          const MemberCondition condition = inspect_member(layout_.member(m), m.id);
          add_measurement(speed_, m, layout_.member(m));
          for (std::size_t c = 0; c < selection_.where.size(); ++c)
            matched[c] = matched[c] || scene_matches(m.scene, {selection_.where[c]});
          if (!selection_.selects(m)) return;
          if (condition.state != MemberState::complete && !copy_source(m, condition)) {
            ++pending;
            any_3d = any_3d || m.scene.at("dim").get<int>() == 3;
          }
        },
        [](std::size_t, const std::string&) {});
    require_matches(campaign_.source, selection_, matched);
    estimate_.pending = pending;
    if (pending > 0) {
      const Concurrency conc = choose_concurrency(usable_cores(), static_cast<int>(pending), any_3d, 0, 0);
      estimate_.jobs = conc.jobs;
      estimate_.threads = conc.threads;
    }
  }

  void print_header() const {
    out_ << "campaign " << campaign_.name;
    if (!campaign_.description.empty()) out_ << ": " << escape_controls(campaign_.description);
    out_ << "\nresults: " << layout_.root.string() << "\n";
    out_ << std::left << std::setw(5) << "#" << std::setw(12) << "state" << std::setw(4) << "dim" << std::setw(12)
         << "nodes" << std::setw(14) << "kt" << std::setw(12) << "node-steps" << std::setw(10) << "seconds"
         << std::setw(10) << "memory"
         << "member (parameters)\n";
  }

  // Seconds: what the member took when it has run, else the estimate ("~"); "copy" for a copy.
  std::string seconds_column(const Member& m, const CostEstimate& c, int dim, bool pending, bool copied) const {
    if (copied) return "copy";
    io::MemberStatus measured;
    if (!pending) {
      try {
        measured = io::read_member_status(layout_.member(m).h5.string());
      } catch (const std::exception&) {
      }
    }
    if (!pending && std::isfinite(measured.wall_seconds)) return format_number(measured.wall_seconds);
    std::string seconds = "~";  // append(): GCC 12 -O3 reports a false -Wrestrict on "literal" + string
    seconds.append(format_number(estimated_member_seconds(c, dim, pending ? estimate_.threads : 1, speed_)));
    return seconds;
  }

  // The row of member m, the i-th of the whole campaign in plan order.
  void print_row(const Member& m, std::size_t i) {
    if (!selection_.selects(m)) return;
    ++totals_.members;
    const MemberCondition condition = inspect_member(layout_.member(m), m.id);
    ++totals_.counts[condition.state];
    const int dim = m.scene.at("dim").get<int>();
    const CostEstimate c = estimate_cost(m.scene, &speed_.lengths);
    const std::optional<FinishedMember> copy_from = copy_source(m, condition);
    if (copy_from) ++totals_.copies;
    const bool pending = condition.state != MemberState::complete && !copy_from;
    if (pending) {
      totals_.node_steps += c.node_steps();
      totals_.node_kt += static_cast<double>(c.nodes) * c.kt_span;
      totals_.peak_memory = std::max(totals_.peak_memory, c.memory_bytes);
      const double estimate = estimated_member_seconds(c, dim, estimate_.threads, speed_);
      estimate_.member_seconds += estimate;
      totals_.longest = std::max(totals_.longest, estimate);
      summary_.pending_seconds[m.id] = estimate;
    }
    std::string params;
    for (const auto& [key, value] : m.parameters) params += (params.empty() ? "" : ", ") + key + "=" + value.dump();
    // The index never runs into the state: past 9999 members the column widens.
    out_ << std::left << std::setw(4) << i << ' ' << std::setw(12) << state_name(condition.state) << std::setw(4) << dim
         << std::setw(12) << c.nodes << std::setw(14) << ((c.kt_is_bound ? "<=" : "") + format_number(c.kt_span))
         << std::setw(12) << format_number(c.node_steps()) << std::setw(10)
         << seconds_column(m, c, dim, pending, copy_from.has_value()) << std::setw(10) << format_bytes(c.memory_bytes)
         << m.dir_name();
    if (!m.case_name.empty() || !params.empty())
      out_ << " (" << (m.case_name.empty() ? "" : "case " + m.case_name + (params.empty() ? "" : "; ")) << params << ")";
    if (copy_from) out_ << "  -- finished in " << copy_from->campaign << ": `study run` copies it";
    else if (!condition.reason.empty()) out_ << "  -- " << condition.reason;
    if (pending) out_ << memory_note(c);
    out_ << "\n";
  }

  // The count per state, the copies and the folders that are no member's.
  void print_counts() {
    auto& counts = totals_.counts;
    out_ << totals_.members << " members: " << counts[MemberState::complete] << " complete, " << counts[MemberState::fresh]
         << " new, " << counts[MemberState::running] << " running, " << counts[MemberState::interrupted]
         << " interrupted, " << counts[MemberState::failed] << " failed, " << counts[MemberState::unstable]
         << " unstable, " << counts[MemberState::stopped] << " stopped";
    if (counts[MemberState::unreadable] > 0) out_ << ", " << counts[MemberState::unreadable] << " unreadable";
    if (!selection_.everything())
      out_ << " (the " << totals_.members << " of " << totals_.index << " that --case / --where select)";
    out_ << "\n";
    const std::size_t copies = totals_.copies;
    if (copies > 0)
      out_ << copies << " of them finished in other campaigns under " << layout_.root.parent_path().string()
           << " (same scene and physics version): `study run` copies " << (copies > 1 ? "them" : "it")
           << " instead of running (--no-reuse runs " << (copies > 1 ? "them" : "it") << ")\n";
    out_ << describe_stray_folders(strays_);
  }

  // The cost of what is not complete, the estimated wall time and the speed corrections.
  void print_cost() const {
    out_ << "cost of what is not complete: " << format_number(totals_.node_kt) << " node-kt";
    if (totals_.node_steps > 0) out_ << ", " << format_number(totals_.node_steps) << " node-steps";
    out_ << "\n";
    if (estimate_.pending == 0) return;
    out_ << "estimated wall time: " << format_duration(estimate_.wall_seconds) << " ("
         << format_number(estimate_.wall_seconds) << " s) for " << estimate_.pending << " members, " << estimate_.jobs
         << " at once x " << estimate_.threads << " thread" << (estimate_.threads > 1 ? "s" : "")
         << "; largest member needs " << format_bytes(totals_.peak_memory) << " of memory (this machine has "
         << format_bytes(physical_memory_bytes()) << ")\n";
    for (int dim : {2, 3}) {
      const SpeedCalibration& k = speed_.for_dim(dim);
      if (k.members > 0)
        out_ << "  " << dim << "D cost model corrected by x" << format_number(k.factor) << " from the measured speed of "
             << k.members << " member" << (k.members > 1 ? "s" : "") << " that ran\n";
      if (k.length_members > 0)
        out_ << "  " << dim << "D phases that end on a condition counted x" << format_number(k.length_factor)
             << " their model length, as " << k.length_members << " member" << (k.length_members > 1 ? "s" : "")
             << " that ran took\n";
    }
    out_ << "  (seconds: '~' estimated from the cost model, docs/guide/running.md \"Time and memory estimates\"; a phase that ends on a\n"
            "   condition counts at its expected end, a theta/beta stop at its cap)\n";
  }

  const Campaign& campaign_;
  const ResultsLayout& layout_;
  const MemberSelection& selection_;
  std::ostream& out_;
  const ReusableMembers elsewhere_;
  MeasuredSpeed speed_;
  std::set<std::string> strays_;
  CampaignEstimate estimate_;
  PlanTotals totals_;
  PlanSummary summary_;
};

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
  return PlanPrinter(plan_campaign, layout, selection, out).print();
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
