// The progress `study run` shows: the line (share done, elapsed, ETA; a bar on a terminal),
// a plain line per change elsewhere, and the ETA smoothed so that its projected end does not
// swing by more than a factor 1.5 within a minute once members have reported
// (study/run/eta_smoothing.hpp), tested on synthetic progress.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "study/run/campaign_progress.hpp"
#include "study/run/eta_smoothing.hpp"
#include "study/state/campaign_survey.hpp"
#include "study/slurm/slurm_queue.hpp"
#include "tests/study/support/study_test_support.hpp"

using namespace capsule::study;
namespace fs = std::filesystem;

namespace {

// A one-minute campaign whose raw ETA jumps as members start, report and finish: the true
// remaining time times a factor that changes every 10 s (0.8, 1.6, 1.1, 1.4, 0.75, 1.2), the
// kind of swing `study run` showed (22 s, 1 min 04 s, 41 s, 55 s, 31 s within one minute).
double raw_eta(double t, double end) {
  static const double factor[] = {0.8, 1.6, 1.1, 1.4, 0.75, 1.2};
  const int k = std::min(5, static_cast<int>(t / 10.0));
  return std::max(0.0, (end - t) * factor[k]);
}

double ratio(const std::vector<double>& v) {
  return *std::max_element(v.begin(), v.end()) / *std::min_element(v.begin(), v.end());
}

}  // namespace

TEST_CASE("the smoothed ETA's projected end stays within a factor 1.5 over the first minute", "[study]") {
  const double end = 60.0, first_report = 3.0;
  EtaSmoother smoother;
  std::vector<double> raw_ends, shown_ends;
  for (double t = 0; t < end; t += 1.0) {
    const double raw = raw_eta(t, end);
    const double shown = smoother.update(t, raw, t >= first_report);
    if (t < first_report) {
      CHECK(shown == Approx(raw));  // nothing reported yet: the model's ETA as it is
      continue;
    }
    INFO("t = " << t << ", raw " << raw << ", shown " << shown);
    CHECK(shown > 0);  // never "0s" while work is left
    raw_ends.push_back(t + raw);
    shown_ends.push_back(t + shown);
  }
  CHECK(ratio(raw_ends) > 1.8);    // the raw ETA swings
  CHECK(ratio(shown_ends) <= 1.5 + 1e-9);  // the shown one does not
  // And it ends near the truth: within 20 % at the last second.
  CHECK(shown_ends.back() == Approx(end).epsilon(0.2));
  CHECK(smoother.update(end, 0.0, true) == 0.0);  // all done
}

TEST_CASE("the smoothed ETA follows a lasting change in a few minutes, and starts again when its end has passed", "[study]") {
  // The model said 5 minutes; the members' measured speed says 10.
  EtaSmoother smoother;
  double shown = 0;
  for (double t = 0; t <= 240; t += 1.0) shown = smoother.update(t, (t < 5 ? 300.0 : 600.0) - t, true);
  CHECK(240 + shown == Approx(600).epsilon(0.05));
  // Far longer than shown: once the end shown has passed, the raw ETA again.
  EtaSmoother late;
  late.update(0, 10, true);
  double after = 0;
  for (double t = 1; t <= 20; t += 1.0) after = late.update(t, 100.0, true);
  CHECK(after > 0);
}

TEST_CASE("the progress line names the share done, the elapsed time and the ETA", "[study]") {
  ProgressCounts c;
  c.done = 1;
  c.running = 2;
  c.left = 1;
  c.fraction_done = 0.314;
  CHECK(progress_line("demo", c, 65, 140, true) ==
        "campaign demo [######--------------] 31% | 1 done, 2 running, 1 left | 1m05s elapsed, ETA 2m20s");
  CHECK(progress_line("demo", c, 65, 140, false) ==
        "campaign demo 31% | 1 done, 2 running, 1 left | 1m05s elapsed, ETA 2m20s");
  c.fraction_done = 0.999;  // not 100 % while members run
  CHECK(progress_line("demo", c, 65, 1, false).find(" 99% |") != std::string::npos);
  CHECK(progress_line("demo", c, 65, 0.2, false).find("ETA <1s") != std::string::npos);  // not "0s" while members run
  ProgressCounts all;
  all.done = 4;
  all.fraction_done = 1.0;
  CHECK(progress_line("demo", all, 80, 5, false) == "campaign demo 100% | 4 done, 0 running, 0 left | 1m20s elapsed, ETA 0s");
}

TEST_CASE("off a terminal the progress is a plain line per change, on a terminal one redrawn line", "[study]") {
  const fs::path dir = testing::scratch_dir("progress_lines");
  testing::write_text(dir / "c.json", testing::tiny_campaign("lines", {0.01, 0.02}, 1, 1).dump());
  const CampaignSurvey survey = survey_campaign((dir / "c.json").string(), dir / "results", slurm_queue);
  ProgressCounts c;
  c.left = 2;
  std::ostringstream plain;
  {
    CampaignProgress p(survey, {0, 1}, 1, 1, false, plain);
    p.show(c, 0);
    p.show(c, 1);  // nothing changed: no line
    c.left = 1;
    c.running = 1;
    p.show(c, 2);  // a member started
    p.show(c, 3);
    p.show(c, 310);  // five minutes without a change: a line all the same
    p.finish();
  }
  const std::string text = plain.str();
  INFO(text);
  CHECK(std::count(text.begin(), text.end(), '\n') == 3);
  CHECK(text.find('\r') == std::string::npos);
  CHECK(text.find('[') == std::string::npos);
  CHECK(text.find("0 done, 1 running, 1 left | 2s elapsed") != std::string::npos);

  std::ostringstream terminal;
  {
    CampaignProgress p(survey, {0, 1}, 1, 1, true, terminal);
    p.show(c, 0);
    p.show(c, 1);
    p.finish();
  }
  const std::string drawn = terminal.str();
  CHECK(std::count(drawn.begin(), drawn.end(), '\r') == 2);
  CHECK(std::count(drawn.begin(), drawn.end(), '\n') == 1);
  CHECK(drawn.find("[--------------------] 0%") != std::string::npos);
  fs::remove_all(dir);
}
