// write_member_shapes(): `capsule shapes` (docs/guide/member-files.md "Shapes of a finished member").
#include "solver/run/shape_rerun.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "build_info.hpp"
#include "common/json_text.hpp"
#include "solver/io/output_path.hpp"
#include "solver/io/state_archive.hpp"
#include "solver/run/checkpoint.hpp"
#include "solver/run/run_control.hpp"
#include "solver/run/simulation2d.hpp"
#include "solver/run/simulation3d.hpp"
#include "solver/scene/memory_estimate.hpp"
#include "solver/common/short_text.hpp"

namespace capsule {
namespace {

namespace fs = std::filesystem;

// Bad input: nothing was run (exit 2).
struct Refusal : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string number(double x) {
  std::ostringstream s;
  s.precision(10);
  s << x;
  return s.str();
}

// The member as it ran: its file, its rows and its scene.
struct Member {
  fs::path folder;
  std::string file;  // member.h5
  io::MemberData data;
  Scene scene;             // the member file's attribute scene (what ran)
  std::string canonical;   // its canonical text: the identity of the member's restart points
  std::string id;
};

// The first key where scene.json and the member file's scene differ, output keys aside ("" when none).
std::string scene_json_difference(const Scene& from_json_file, const Scene& ran) {
  nlohmann::json a = from_json_file.to_json(), b = ran.to_json();
  a.erase("output");
  b.erase("output");
  const nlohmann::json patch = nlohmann::json::diff(b, a);
  if (patch.empty()) return "";
  const nlohmann::json::json_pointer where(patch[0].at("path").get<std::string>());
  std::string key = where.to_string().substr(1);
  std::replace(key.begin(), key.end(), '/', '.');
  return "key " + message_text(key) + ": " + (a.contains(where) ? message_value(a.at(where)) : "(absent)") +
         " in scene.json, " + (b.contains(where) ? message_value(b.at(where)) : "(absent)") + " in member.h5";
}

Member open_member(const std::string& path) {
  std::error_code ec;
  Member m;
  if (!fs::exists(path, ec)) throw Refusal(path + ": no such member folder");
  const bool folder = fs::is_directory(path, ec);
  m.folder = folder ? fs::path(path) : fs::path(path).parent_path();
  m.file = folder ? (fs::path(path) / "member.h5").string() : path;
  if (folder && !fs::exists(m.file, ec)) {
    if (fs::exists(m.file + ".partial", ec))
      throw Refusal(m.file + ": the member has not ended (only member.h5.partial: it is running or was interrupted; "
                             "`study run` finishes it)");
    throw Refusal(path + ": not a member folder (it holds no member.h5; a member folder is "
                         "results/<campaign>/members/<member>/)");
  }
  try {
    m.data = io::read_member(m.file);
  } catch (const std::exception& e) {
    throw Refusal(e.what());
  }
  if (!m.data.complete() && !m.data.unstable())
    throw Refusal(m.file + ": the member has not ended (status \"" + message_text(m.data.status) +
                  "\"): shapes come from a member that ended complete or unstable");
  if (const std::string missing = io::missing_series(m.data); !missing.empty()) throw Refusal(missing);
  if (!m.data.attributes.contains("scene") || !m.data.attributes["scene"].is_object())
    throw Refusal(m.file + ": no attribute scene: not a member file");
  try {
    m.scene = Scene::from_json(m.data.attributes["scene"], m.file + " (attribute scene)");
  } catch (const std::exception& e) {
    throw Refusal(std::string(e.what()) + " (this build cannot run the member's scene)");
  }
  m.canonical = m.scene.to_json().dump();
  m.id = m.data.attributes.value("member_id", std::string());
  const fs::path scene_json = m.folder / "scene.json";
  if (folder && fs::exists(scene_json, ec)) {
    Scene s;
    try {
      s = Scene::load(scene_json.string());
    } catch (const std::exception& e) {
      throw Refusal(e.what());
    }
    if (const std::string d = scene_json_difference(s, m.scene); !d.empty())
      throw Refusal(scene_json.string() + ": not the scene " + m.file + " ran (" + d + ")");
  }
  return m;
}

// The times asked for, sorted, each within the member's rows.
std::vector<double> times_within(const Member& m, std::vector<double> at_kt) {
  if (at_kt.empty()) throw Refusal("--at-kt: no time given");
  std::sort(at_kt.begin(), at_kt.end());
  at_kt.erase(std::unique(at_kt.begin(), at_kt.end()), at_kt.end());
  const std::vector<double>& kt = m.data.series.at("kt");
  for (double t : at_kt)
    if (!(t >= kt.front() && t <= kt.back()))
      throw Refusal(m.file + ": --at-kt " + number(t) + " is outside the member's run: its rows span kt = " +
                    number(kt.front()) + " to " + number(kt.back()) + " (status " + message_text(m.data.status) + ")");
  return at_kt;
}

std::string default_output(const Member& m, const std::string& given) {
  std::error_code ec;
  if (fs::is_directory(given, ec)) return (m.folder / "shapes.h5").string();
  std::string base = m.file;
  if (base.size() > 3 && base.substr(base.size() - 3) == ".h5") base.resize(base.size() - 3);
  return base + "_shapes.h5";
}

void check_output(const Member& m, const std::string& out) {
  if (const std::string problem = io::output_path_problem(out); !problem.empty()) throw Refusal(problem);
  std::error_code ec;
  for (const fs::path& kept : {fs::path(m.file), m.folder / "scene.json", fs::path(m.file + ".restart")})
    if (fs::weakly_canonical(out, ec) == fs::weakly_canonical(kept, ec))
      throw Refusal(out + ": is the member's own file; the shapes go to a separate file (-o shapes.h5)");
}

// The member's restart point when it may be continued: same identity, and its last row before
// the first time asked for. An explicit one that may not is refused; the member's own is skipped.
std::unique_ptr<io::StateArchive> usable_restart_point(const Member& m, const std::string& given, double first_kt,
                                                      bool quiet) {
  const std::string path = given.empty() ? restart_path_for(m.file) : given;
  std::error_code ec;
  if (!fs::exists(path, ec)) {
    if (!given.empty()) throw Refusal(given + ": no such restart point");
    return nullptr;
  }
  std::string why;
  try {
    auto a = std::make_unique<io::StateArchive>(io::StateArchive::read(path));
    why = identity_mismatch(*a, current_identity(m.canonical, m.id));
    if (why.empty()) {
      const std::vector<double>& kt = a->doubles("member.series.kt");
      const double last = kt.empty() ? -1.0 : kt.back();
      if (first_kt > last + 0.5 * m.scene.output.interval_kt) return a;
      why = "its last row is at kt = " + number(last) + ", not before the first time asked for (" + number(first_kt) + ")";
    }
  } catch (const std::exception& e) {
    why = e.what();
  }
  if (!given.empty()) throw Refusal(path + ": this restart point cannot be continued: " + why);
  if (!quiet) std::cerr << "capsule: the member's restart point " << path << " is not used (" << why << "); rerunning from kt = 0\n";
  return nullptr;
}

struct Rerun {
  std::unique_ptr<io::MemberWriter> out;
  std::string status;
  std::string from = "kt = 0";  // where it started
  long first_step = 0;
  double wall_seconds = 0;
};

Rerun rerun(const Scene& scene, const std::string& output, io::StateArchive* resume, bool quiet) {
  const auto t0 = std::chrono::steady_clock::now();
  Rerun r;
  auto attempt = [&](io::StateArchive* from) {
    r.out = std::make_unique<io::MemberWriter>(output);  // its path names the snapshots
    r.out->hold_in_memory();
    r.first_step = from ? static_cast<long>(from->integer("sim.steps")) : 0;
    r.from = from ? "the member's restart point at step " + std::to_string(r.first_step) + " (after the row at kt = " +
                        number(from->doubles("member.series.kt").back()) + ")"
                  : "kt = 0";
    RunControl control;
    control.quiet = quiet;
    control.checkpoint = {0, -1, -1};
    control.resume = from;
    control.stop_after_last_shape = true;
    r.status = scene.dim == 2 ? run_simulation2d(scene, *r.out, control) : run_simulation3d(scene, *r.out, control);
  };
  try {
    attempt(resume);
  } catch (const RestartRefused& e) {
    if (!quiet) std::cerr << "capsule: the restart point is not used (" << e.what() << "); rerunning from kt = 0\n";
    attempt(nullptr);
  }
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

void note(SeriesDifference& d, const std::string& column, double a, double b, double kt) {
  if (std::memcmp(&a, &b, sizeof a) == 0) return;
  if (std::isnan(a) && std::isnan(b)) return;
  d.bitwise = false;
  const double diff = std::isnan(a) || std::isnan(b) ? std::numeric_limits<double>::infinity() : std::abs(a - b);
  if (d.column.empty() || diff > d.largest) d.largest = diff, d.column = column, d.at_kt = kt;
}

std::string describe(const SeriesDifference& d) {
  std::ostringstream s;
  if (!d.row_count.empty()) return d.row_count;
  if (d.bitwise) s << "its " << d.rows << " rows reproduce the member's series bitwise";
  else s << "its " << d.rows << " rows differ from the member's series by up to " << d.largest << " (" << d.column
         << " at kt = " << d.at_kt << ")";
  if (!d.not_compared.empty()) {
    s << "; not compared, in only one of the two:";
    for (const auto& c : d.not_compared) s << " " << c;
  }
  return s.str();
}

void record(io::MemberWriter& out, const Member& m, const Scene& scene, const Rerun& r, const SeriesDifference& d,
            long threads) {
  out.set_scene(scene.to_json());  // the member's, with the times and snapshots asked for
  out.set_attribute("member_id", m.id);
  out.set_attribute("member_file", fs::absolute(m.file).lexically_normal().string());
  out.set_attribute("member_code_version", m.data.attributes.value("code_version", std::string()));
  out.set_attribute("member_physics_version", m.data.attributes.value("physics_version", std::string()));
  out.set_attribute("member_threads", m.data.attributes.value("threads", 0L));
  out.set_attribute("member_steps", m.data.attributes.value("steps", 0L));
  out.set_attribute("code_version", build::code_version);
  out.set_attribute("physics_version", choice_name(m.scene.physics_version));
  out.set_attribute("dim", static_cast<long>(m.scene.dim));
  out.set_attribute("threads", threads);
  out.set_attribute("rerun_from", r.from);
  const auto steps = out.attributes().find("steps");  // set by the driver: the step it stopped at
  const long stopped_at = steps == out.attributes().end() ? 0L : std::get<long>(steps->second);
  out.set_attribute("rerun_steps", stopped_at - r.first_step);
  out.set_attribute("stopped_at_kt", out.series().at("kt").back());
  out.set_attribute("wall_seconds", r.wall_seconds);
  out.set_attribute("finished", utc_now());
  out.set_attribute("series_rows_compared", static_cast<long>(d.rows));
  out.set_attribute("series_max_difference", d.largest);
  out.set_attribute("series_check", describe(d));
}

bool reproduced(const SeriesDifference& d) { return d.row_count.empty() && d.bitwise; }

// Why the rerun is not the member's run, with what may differ between the two.
std::string not_reproduced(const Member& m, const SeriesDifference& d, long threads) {
  const auto text = [&](const char* key) { return m.data.attributes.value(key, std::string("(none)")); };
  std::ostringstream s;
  s << "the rerun does not reproduce " << m.file << " bitwise: " << describe(d) << ". The member was written by code " << text("code_version") << ", physics " << text("physics_version")
    << ", " << m.data.attributes.value("threads", 0L) << " threads; this rerun by code " << build::code_version
    << ", physics " << choice_name(m.scene.physics_version) << ", " << threads << " threads";
  return s.str();
}

// The .vtp frames and the .pvd a refused rerun wrote.
void remove_snapshots(const io::MemberWriter& out, const Scene& scene) {
  if (scene.output.snapshots != Snapshots::vtk) return;
  std::error_code ec;
  for (double kt : out.shape_times()) fs::remove(snapshot_path(out.final_path(), kt), ec);
  fs::remove(snapshot_base(out.final_path()) + ".pvd", ec);
}

}  // namespace

SeriesDifference compare_series(const io::MemberWriter& rerun, const io::MemberData& member) {
  SeriesDifference d;
  d.rows = rerun.rows();
  const auto member_kt = member.series.find("kt");
  const std::size_t member_rows = member_kt == member.series.end() ? 0 : member_kt->second.size();
  if (member_rows < d.rows || rerun.beta().size() > member.beta.size()) {
    d.bitwise = false;
    d.largest = std::numeric_limits<double>::infinity();
    d.row_count = "the rerun has " + std::to_string(d.rows) + " rows, the member only " + std::to_string(member_rows);
    return d;
  }
  const std::vector<double>& kt = rerun.series().at("kt");
  for (const auto& [name, values] : rerun.series()) {
    const auto theirs = member.series.find(name);
    if (theirs == member.series.end()) {
      d.not_compared.push_back(name);
      continue;
    }
    for (std::size_t r = 0; r < d.rows; ++r) note(d, name, values[r], theirs->second[r], kt[r]);
  }
  for (const auto& [name, values] : member.series)
    if (!rerun.series().count(name)) d.not_compared.push_back(name);
  for (std::size_t r = 0; r < rerun.beta().size(); ++r) {
    if (rerun.beta()[r].size() != member.beta[r].size()) {
      d.not_compared.push_back("beta");
      break;
    }
    for (std::size_t i = 0; i < rerun.beta()[r].size(); ++i) note(d, "beta", rerun.beta()[r][i], member.beta[r][i], kt[r]);
  }
  return d;
}

int write_member_shapes(const ShapeRerunOptions& o) {
  try {
    const Member m = open_member(o.member);
    const std::vector<double> times = times_within(m, o.at_kt);
    if (o.snapshots == Snapshots::vtk && m.scene.dim != 3)
      throw Refusal(m.file + ": --snapshots vtk: snapshots are written for 3D members only; this member is 2D");
    const std::string output = o.output_path.empty() ? default_output(m, o.member) : o.output_path;
    check_output(m, output);
    Scene scene = m.scene;
    scene.output.shapes_at_kt = times;
    scene.output.snapshots = o.snapshots;
    if (const std::string too_big = memory_refusal(scene); !too_big.empty()) throw Refusal(m.file + ": " + too_big);
    std::unique_ptr<io::StateArchive> resume = usable_restart_point(m, o.restart_path, times.front(), o.quiet);

    const long member_threads = m.data.attributes.value("threads", 0L);
    const long threads = o.threads > 0 ? o.threads : member_threads > 0 ? member_threads : omp_get_max_threads();
    omp_set_num_threads(static_cast<int>(threads));
    if (!o.quiet)
      std::cerr << "capsule: rerunning " << m.file << " " << (resume ? "from its restart point" : "from kt = 0")
                << " to kt = " << number(times.back()) << " (its rows end at kt = " << number(m.data.series.at("kt").back())
                << ") with " << threads << " threads\n";
    Rerun r = rerun(scene, output, resume.get(), o.quiet);
    resume.reset();
    if (r.status != kShapesWritten) {
      std::cerr << "capsule: the rerun of " << m.file << " ended before kt = " << number(times.back()) << ": " << r.status
                << "; nothing written\n";
      remove_snapshots(*r.out, scene);
      return 1;
    }
    const SeriesDifference d = compare_series(*r.out, m.data);
    record(*r.out, m, scene, r, d, threads);
    if (!reproduced(d)) {
      std::cerr << "capsule: WARNING: " << not_reproduced(m, d, threads) << "\n";
      if (!o.accept_difference) {
        remove_snapshots(*r.out, scene);
        std::cerr << "capsule: nothing written (--accept-difference writes the rerun's shapes all the same)\n";
        return 1;
      }
      r.out->set_attribute("series_check", "NOT REPRODUCED, written with --accept-difference: " + describe(d));
    }
    r.out->write_shapes_file(output);
    std::cerr << "capsule: " << output << ": " << r.out->shape_times().size() << " shapes of " << m.file << ", rerun from "
              << r.from << " to kt = " << number(r.out->series().at("kt").back()) << " in "
              << std::get<long>(r.out->attributes().at("rerun_steps")) << " steps (the member ran "
              << m.data.attributes.value("steps", 0L) << ") and " << number(r.wall_seconds) << " s; " << describe(d) << "\n";
    return 0;
  } catch (const Refusal& e) {
    std::cerr << "capsule: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "capsule: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace capsule
