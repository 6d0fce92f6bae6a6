#include "study/run/campaign_runner.hpp"
#include "study/campaign/campaign_error.hpp"

#include <algorithm>

#include <cerrno>
#include <cstdlib>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <stdexcept>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>
#include <functional>
#include <map>
#include <set>
#include <thread>
#include <vector>

#include "build_info.hpp"
#include "study/run/campaign_progress.hpp"
#include "study/run/capsule_binary.hpp"
#include "study/plan/concurrency.hpp"
#include "study/state/exit_status.hpp"
#include "study/state/member_reuse.hpp"
#include "study/run/joblog.hpp"
#include "study/campaign/member_filter.hpp"
#include "study/campaign/member_selection.hpp"
#include "study/run/member_wrapper.hpp"
#include "study/run/parallel_arguments.hpp"
#include "study/run/provenance.hpp"
#include "study/run/run_lock.hpp"
#include "study/state/run_record.hpp"
#include "study/run/script_path.hpp"

namespace capsule::study {

namespace fs = std::filesystem;

namespace {

volatile sig_atomic_t child_pid = 0;
volatile sig_atomic_t stop_signal_seen = 0;  // SIGTERM or SIGINT received while members ran

// SIGTERM to study is passed on to GNU Parallel (which then stops starting members and
// ends), so `kill <study pid>` still ends in a summary.
extern "C" void forward_sigterm(int signal) {
  stop_signal_seen = signal;
  if (child_pid > 0) ::kill(static_cast<pid_t>(child_pid), SIGTERM);
}

// Ctrl-C reaches GNU Parallel through the terminal's process group; study only notes it.
extern "C" void note_interrupt(int signal) { stop_signal_seen = signal; }

// Runs argv (no shell) and waits. Ctrl-C reaches GNU Parallel through the terminal's
// process group; study only notes it meanwhile so it can still print the summary.
int run_and_wait(const std::vector<std::string>& argv, const std::function<void(long)>& started,
                 const std::function<void()>& every_second) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  struct sigaction note {}, forward {}, old_int {}, old_term {};
  note.sa_handler = note_interrupt;
  forward.sa_handler = forward_sigterm;
  sigaction(SIGINT, &note, &old_int);
  sigaction(SIGTERM, &forward, &old_term);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
  if (pid == 0) {
    sigaction(SIGINT, &old_int, nullptr);
    sigaction(SIGTERM, &old_term, nullptr);
    // GNU Parallel builds the command it sends over ssh around $SHELL; with SHELL unset
    // (cron, CI, `env -i`) every remote member fails at once. /bin/sh is what it would pick.
    if (std::getenv("SHELL") == nullptr) ::setenv("SHELL", "/bin/sh", 1);
    ::execvp(args[0], args.data());
    std::fprintf(stderr, "study: cannot run %s: %s\n", args[0], std::strerror(errno));
    ::_exit(127);
  }
  child_pid = pid;
  started(static_cast<long>(pid));
  int status = 0;
  // Poll, so the campaign's progress line can be redrawn while the members run.
  for (int ticks = 0;; ++ticks) {
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) break;
    if (r < 0 && errno != EINTR) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    if (ticks % 10 == 9 && every_second) every_second();
  }
  child_pid = 0;
  sigaction(SIGINT, &old_int, nullptr);
  sigaction(SIGTERM, &old_term, nullptr);
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return 1;
}

}  // namespace

int stop_signal_received() { return stop_signal_seen; }

void print_status(const CampaignSurvey& survey, std::ostream& out) {
  out << "campaign " << survey.campaign.name << ": " << survey.members.size() << " members in "
      << survey.layout.root.string() << "\n";
  for (auto state : kAllMemberStates)
    out << "  " << state_name(state) << ": " << survey.count(state) << "\n";
  for (std::size_t i = 0; i < survey.members.size(); ++i) {
    const auto& c = survey.conditions[i];
    if (c.state == MemberState::complete || c.state == MemberState::fresh) continue;
    out << "  [" << state_name(c.state) << "] " << survey.members[i].dir_name() << ": " << c.reason << "\n";
  }
  if (!survey.note.empty()) out << "  (" << survey.note << ")\n";
  const bool exported = fs::exists(survey.layout.slurm_dir() / "export.json");
  if (survey.count(MemberState::interrupted) + survey.count(MemberState::fresh) + survey.count(MemberState::failed) > 0) {
    if (exported)
      out << "  (exported for Slurm: `study export --slurm` again, then `sh " << (survey.layout.slurm_dir() / "submit.sh").string()
          << "`, submits what is neither complete nor queued; `study run` runs it here instead)\n";
    else
      out << "  (`study run` again runs what is not complete; complete members are kept)\n";
  }
  if (survey.count(MemberState::unreadable) > 0)
    out << "  (an unreadable member file is never deleted or run over: free it, or move it aside to run the member again)\n";
  if (survey.count(MemberState::unstable) + survey.count(MemberState::stopped) > 0)
    out << "  (unstable and stopped members are kept: `study run --rerun-unstable` / `--rerun-stopped` runs them again)\n";
}

namespace {

// The members --case / --where select (checked before anything is written) that need running.
std::vector<std::size_t> members_to_run(const CampaignSurvey& survey, const MemberSelection& selection,
                                        const RunRequest& request) {
  std::vector<std::size_t> to_run;
  for (std::size_t i = 0; i < survey.members.size(); ++i) {
    if (!selection.selects(survey.members[i])) continue;
    if (!needs_run(survey.conditions[i], request.rerun_unstable, request.rerun_stopped)) continue;
    to_run.push_back(i);
  }
  return to_run;
}

// A member another campaign under the same results folder finished is copied, not run again:
// removed from to_run. Returns how many were copied.
std::size_t copy_finished_elsewhere(const CampaignSurvey& survey, std::vector<std::size_t>& to_run, std::ostream& out) {
  std::vector<std::size_t> candidates;
  for (std::size_t i : to_run)
    if (const MemberState st = survey.conditions[i].state; st != MemberState::unstable && st != MemberState::stopped)
      candidates.push_back(i);
  const auto copied = copy_reusable_members(survey.members, candidates, survey.layout, out);
  to_run.erase(std::remove_if(to_run.begin(), to_run.end(),
                              [&](std::size_t i) { return std::find(copied.begin(), copied.end(), i) != copied.end(); }),
               to_run.end());
  return copied.size();
}

// A run.json without "finished" is the record of a run that was killed: kept in the history.
void keep_killed_run_record(const ResultsLayout& layout) {
  if (!fs::exists(layout.run_json())) return;
  std::ifstream in(layout.run_json());
  const nlohmann::json last = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (last.is_object() && !last.contains("finished")) {
    nlohmann::json killed = last;
    killed["ended"] = "killed: no summary was written";
    append_run_history(layout.run_history(), killed);
  }
}

// What the joblog says of this run's rows (those started since start_epoch).
struct JoblogSummary {
  double member_seconds = 0;                               // sum of JobRuntime
  std::map<std::string, std::vector<std::string>> refused;  // host -> members it could not be handed
};

JoblogSummary summarise_joblog(const CampaignSurvey& survey, const std::vector<std::size_t>& to_run, double start_epoch) {
  JoblogSummary summary;
  // A row with exit value 255 is a member GNU Parallel could not hand to its host (ssh's
  // own failure: the wrapper passes on the capsule's status, which is never 255).
  for (const auto& e : read_joblog(survey.layout.joblog())) {
    if (e.start < start_epoch - 1.0) continue;  // this run's rows only
    summary.member_seconds += e.runtime;
    if (e.exit_value == 255 && e.seq >= 1 && static_cast<std::size_t>(e.seq) <= to_run.size())
      summary.refused[e.host].push_back(survey.members[to_run[e.seq - 1]].dir_name());
  }
  return summary;
}

// How GNU Parallel ended: stopped by a signal, failed itself, or some hosts could not be reached.
void report_parallel_end(int parallel_status, const JoblogSummary& joblog, const RunRequest& request,
                         RunOutcome& outcome, nlohmann::json& record, std::ostream& out) {
  record["parallel_exit_status"] = parallel_status;
  // 1-100: that many jobs failed, 101: more; the members' own files tell which. 255 (or any
  // other status) is GNU Parallel's own failure: a bad option or hosts file, no such program.
  if (stop_signal_seen != 0) {
    // GNU Parallel passes the signal on to the running members and ends with 255.
    out << "study: stopped by signal " << stop_signal_seen
        << ": the running members were told to write a restart point; `study run` continues them\n";
    record["stopped_by_signal"] = static_cast<int>(stop_signal_seen);
  } else if (parallel_status > 101) {
    out << "study: GNU Parallel itself failed (exit status " << parallel_status
        << "; its message is above): members it did not start are still new\n";
    outcome.tool_failed = true;
    record["parallel_failed"] = true;
  }
  for (const auto& [host, members] : joblog.refused) {
    out << "study: host " << host << " could not be reached (exit 255) for " << members.size() << " member"
        << (members.size() == 1 ? "" : "s") << ":";
    for (const auto& m : members) out << " " << m;
    out << " (each tried again on another host, up to --retries " << request.retries << ")\n";
    record["unreachable_hosts"][host] = members;
  }
}

// The capsule binary and the version its member files record.
struct CapsuleBinary {
  fs::path path;
  std::string code_version;
};

// Hands the members of to_run to GNU Parallel and waits; returns the members no host it was
// given could be reached for.
std::set<std::string> run_members(const CampaignSurvey& survey, const std::vector<std::size_t>& to_run,
                                  const RunRequest& request, const CapsuleBinary& capsule, RunLock& lock,
                                  RunOutcome& outcome, nlohmann::json& record, std::ostream& out) {
  bool any_3d = false;
  for (std::size_t i : to_run) any_3d = any_3d || survey.members[i].scene.at("dim").get<int>() == 3;
  const Concurrency conc =
      choose_concurrency(usable_cores(), static_cast<int>(to_run.size()), any_3d, request.jobs, request.threads);
  record["jobs"] = conc.jobs;
  record["threads"] = conc.threads;
  record["hosts_file"] = request.hosts_file;

  std::string job_list;
  for (std::size_t i : to_run) job_list += survey.layout.member(survey.members[i]).dir.string() + "\n";
  write_file_atomically(survey.layout.jobs_file(), job_list);
  write_member_wrapper(survey.layout.wrapper(), {survey.campaign.name, own_executable(), capsule.path,
                                                 request.checkpoint_seconds, capsule.code_version});
  write_file_atomically(survey.layout.run_json(), record.dump(2) + "\n");

  out << "running " << to_run.size() << " of " << survey.members.size() << " members (" << conc.jobs
      << " at once" << (request.hosts_file.empty() ? "" : " per host") << " x " << conc.threads << " thread"
      << (conc.threads > 1 ? "s" : "") << ")\n"
      << std::flush;
  const double start_epoch =
      std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
  const auto start = std::chrono::steady_clock::now();
  CampaignProgress progress(survey, to_run, conc.jobs, conc.threads, request.progress_bar, out);
  const int parallel_status = run_and_wait(parallel_arguments(survey.layout, request, conc),
                                           [&lock](long pid) { lock.record(pid); }, [&] { progress.tick(); });
  progress.finish();
  outcome.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.ran = to_run.size();
  const JoblogSummary joblog = summarise_joblog(survey, to_run, start_epoch);
  outcome.member_seconds = joblog.member_seconds;
  report_parallel_end(parallel_status, joblog, request, outcome, record, out);
  std::set<std::string> refused_members;
  for (const auto& [host, members] : joblog.refused) refused_members.insert(members.begin(), members.end());
  return refused_members;
}

// The verdict, from the members' own files: the status printed, the exit code, run.json and
// the run history written.
void finish_run(CampaignSurvey& survey, const std::set<std::string>& refused_members, RunOutcome& outcome,
                nlohmann::json& record, std::ostream& out) {
  for (std::size_t i = 0; i < survey.members.size(); ++i)
    survey.conditions[i] = inspect_member(survey.layout.member(survey.members[i]), survey.members[i].id);
  print_status(survey, out);
  if (outcome.ran > 0)
    out << "wall " << outcome.wall_seconds << " s for " << outcome.member_seconds
        << " s of member run time (concurrency " << (outcome.wall_seconds > 0 ? outcome.member_seconds / outcome.wall_seconds : 0)
        << ")\n";
  // A member no host could be reached for is the tool's failure (exit 1), not the member's.
  for (std::size_t i = 0; i < survey.members.size(); ++i)
    if (refused_members.count(survey.members[i].dir_name()) && survey.conditions[i].state != MemberState::complete) {
      out << "study: " << survey.members[i].dir_name() << " did not run: no host it was given could be reached\n";
      outcome.tool_failed = true;
    }
  outcome.exit_code = outcome.tool_failed ? exit_failure : members_exit_code(survey);

  record["finished"] = utc_now_iso8601();
  record["wall_seconds"] = outcome.wall_seconds;
  record["member_seconds"] = outcome.member_seconds;
  nlohmann::json counts;
  for (auto state : kAllMemberStates)
    counts[state_name(state)] = survey.count(state);
  record["counts"] = counts;
  record["exit_status"] = outcome.exit_code;
  write_file_atomically(survey.layout.run_json(), record.dump(2) + "\n");
  append_run_history(survey.layout.run_history(), record);
}

// Refused before anything is written: a dirty build's members could not be reproduced. The
// capsule binary's version is what its member files record: checked here when a member needs
// running, and again by run-member before each member, so a binary rebuilt mid-campaign cannot
// mix versions.
CapsuleBinary checked_capsule_binary(const CampaignSurvey& survey, const RunRequest& request) {
  CapsuleBinary capsule{find_capsule_binary(), ""};
  if (std::any_of(survey.conditions.begin(), survey.conditions.end(), [&](const MemberCondition& c) {
        return needs_run(c, request.rerun_unstable, request.rerun_stopped);
      })) {
    require_committed_build(build::code_version, request.allow_dirty, "study run");
    capsule.code_version = capsule_code_version(capsule.path);
    require_committed_build(capsule.code_version, request.allow_dirty,
                            "study run (capsule binary " + capsule.path.string() + ")");
  }
  return capsule;
}

}  // namespace

RunOutcome run_campaign(const RunRequest& request, const QueueReader& queue, std::ostream& out) {
  CampaignSurvey survey = survey_campaign(request.campaign_file, request.results_dir, queue);
  // --case and --where: checked before anything is written.
  const MemberSelection selection = select_members(request.campaign_file, survey.campaign, request.cases, request.where);
  std::vector<bool> matched(selection.where.size(), false);
  for (const Member& m : survey.members)
    for (std::size_t c = 0; c < selection.where.size(); ++c)
      matched[c] = matched[c] || scene_matches(m.scene, {selection.where[c]});
  require_matches(request.campaign_file, selection, matched);
  const CapsuleBinary capsule = checked_capsule_binary(survey, request);
  // The job list has one member directory per line; the wrapper names the capsule binary.
  require_script_safe("the results folder", survey.layout.root);
  require_script_safe("the capsule binary's path", capsule.path);
  fs::create_directories(survey.layout.root);
  RunLock lock(survey.layout.lock_file(), survey.layout.running_info(), members_in_progress(survey));
  prepare_member_directories(survey);

  std::vector<std::size_t> to_run = members_to_run(survey, selection, request);
  const std::size_t copied_count = request.reuse_finished ? copy_finished_elsewhere(survey, to_run, out) : 0;
  // Under each member's lock, after reading its file again: a Slurm task may have finished one since the survey.
  to_run = clear_members_to_rerun(survey, to_run, request.rerun_unstable, request.rerun_stopped);

  keep_killed_run_record(survey.layout);
  nlohmann::json record = run_record_start(survey.campaign.name, request.campaign_file);
  record["capsule_binary"] = capsule.path.string();
  record["capsule_code_version"] = capsule.code_version;
  record["members"] = survey.members.size();
  record["to_run"] = to_run.size();
  record["copied_from_other_campaigns"] = copied_count;
  if (request.allow_dirty && is_uncommitted_version(build::code_version)) record["allow_dirty"] = true;

  RunOutcome outcome;
  std::set<std::string> refused_members;  // members handed to a host that could not be reached
  if (!to_run.empty()) {
    refused_members = run_members(survey, to_run, request, capsule, lock, outcome, record, out);
  } else {
    // Finished, or kept as they are (running elsewhere, unreadable, unstable, stopped): the
    // summary below says which.
    out << "nothing to run"
        << (request.cases.empty() && request.where.empty() ? "" : " among the members --case / --where select")
        << ": no member needs running (the states are below)\n";
  }
  finish_run(survey, refused_members, outcome, record, out);
  return outcome;
}

}  // namespace capsule::study
