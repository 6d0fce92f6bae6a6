// run_member(): one scene -> one member file (docs/CONTRACTS.md "Member file", "Binaries").
#include "solver/run/run_member.hpp"

#include <omp.h>
#include <unistd.h>

#include <chrono>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <cerrno>
#include <cstdlib>
#include <new>
#include <system_error>

#include "build_info.hpp"
#include "solver/io/member_file.hpp"
#include "solver/io/output_path.hpp"
#include "solver/io/write_guard.hpp"
#include "solver/scene/physical_cell.hpp"
#include "solver/scene/memory_estimate.hpp"
#include "solver/run/progress.hpp"
#include "solver/run/run_control.hpp"
#include "solver/run/simulation2d.hpp"
#include "solver/run/simulation3d.hpp"
#include "solver/scene/scene.hpp"
#include "solver/scene/version.hpp"
#include "solver/common/short_text.hpp"

namespace capsule {
namespace {

std::string host_name() {
  char buf[256] = {};
  if (gethostname(buf, sizeof buf - 1) != 0) return "unknown";
  return buf;
}

// What ran out, when an error is a full disk or a lack of memory ("" when it is neither): such a
// member is interrupted, not ended; its .partial and last good restart point are kept.
std::string exhausted_resource(const std::exception& e) {
  if (dynamic_cast<const std::bad_alloc*>(&e) != nullptr) return "out of memory";
  if (const auto* s = dynamic_cast<const std::system_error*>(&e)) {
    const int code = s->code().value();
    if (s->code().category() == std::generic_category() || s->code().category() == std::system_category()) {
      if (code == ENOSPC || code == EDQUOT) return "no space left on the disk";
      if (code == ENOMEM) return "out of memory";
    }
  }
  return "";
}

struct ResourcesExhausted {
  std::string why;
};

// Ends the process at once with exit 5: HDF5 keeps a file whose flush failed open, and its
// handler at exit tries to close it again and crashes (SIGSEGV in H5F__close_cb, seen on a full
// tmpfs), which would turn a resumable member into one killed by a signal.
[[noreturn]] void end_interrupted() {
  std::cerr.flush();
  std::cout.flush();
  std::_Exit(kExitResourcesExhausted);
}

// Which numerics the scene ran (solver/scene/numerics_preset.hpp): under the dissertation's, every
// item the preset set and every part of the text it does not emulate, a line each.
void record_numerics(io::MemberWriter& out, const Scene& scene) {
  out.set_attribute("numerics", choice_name(scene.numerics));
  if (scene.numerics != Numerics::dissertation) return;
  const auto joined = [](const std::vector<std::string>& lines) {
    std::string text;
    for (const auto& l : lines) text += (text.empty() ? "" : "\n") + l;
    return text;
  };
  out.set_attribute("numerics_emulated", joined(numerics_item_lines(scene.dim, scene.shape)));
  out.set_attribute("numerics_not_emulated", joined(numerics_gap_lines(scene.dim)));
}

}  // namespace

int run_member(const RunOptions& options) {
  if (const std::string problem = io::output_path_problem(options.output_path); !problem.empty()) {
    std::cerr << "capsule: " << problem << "\n";
    return 2;
  }
  Scene scene;
  try {
    scene = Scene::load(options.scene_path);
  } catch (const std::exception& e) {  // SceneError, or an unreadable file
    std::cerr << "capsule: " << e.what() << "\n";
    return 2;
  }
  if (const std::string too_big = memory_refusal(scene); !too_big.empty()) {
    std::cerr << "capsule: " << options.scene_path << ": " << too_big << "\n";
    return 2;
  }
  install_stop_signals();
  io::guard_writes_from_environment();
  if (options.threads > 0) omp_set_num_threads(options.threads);
  const long threads = options.threads > 0 ? options.threads : omp_get_max_threads();

  const auto t0 = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  const std::string restart_path = restart_path_for(options.output_path);
  const std::string canonical = scene.to_json().dump();
  try {
    // A restart point of this very run (scene, physics, build, id) is continued; any other is refused.
    const RestartIdentity identity = current_identity(canonical, options.member_id);
    std::unique_ptr<io::StateArchive> resume = load_restart_point(restart_path, identity, std::cerr);
    double wall_before = 0;  // wall seconds of the earlier sessions up to their last restart point
    long restarts = 0;
    std::string started = utc_now();
    if (resume) {
      wall_before = resume->number("run.wall_seconds");
      restarts = static_cast<long>(resume->integer("run.restarts")) + 1;
      started = resume->text("run.started");
      const long saved_threads = static_cast<long>(resume->integer("run.threads"));
      if (saved_threads != threads)
        std::cerr << "capsule: the restart point was written with " << saved_threads << " threads, this run has "
                  << threads << ": the rows match an uninterrupted run bitwise only for equal thread counts\n";
    }

    // One attempt: from the restart point when there is one, else from the start.
    std::string status;
    auto attempt = [&](io::MemberWriter& out) {
      out.set_scene(scene.to_json());
      out.set_attribute("member_id", options.member_id);
      out.set_attribute("code_version", build::code_version);
      out.set_attribute("physics_version", choice_name(scene.physics_version));
      record_numerics(out, scene);
      out.set_attribute("host", host_name());
      out.set_attribute("started", started);
      out.set_attribute("dim", static_cast<long>(scene.dim));
      out.set_attribute("threads", threads);
      out.set_attribute("restarts", restarts);
      // A cell given in physical units: what kt = 1 and a length of a are, in seconds and
      // micrometres (the scene attribute holds the physical block and its groups).
      if (scene.physical) {
        const PhysicalGroups g = physical_groups(*scene.physical, scene.law, scene.conventions.sls_viscosity);
        out.set_attribute("seconds_per_kt", g.time_unit_s);
        out.set_attribute("micrometres_per_a", g.length_unit_um);
      }
      write_starting_progress(progress_path_for(options.output_path));
      out.checkpoint();  // a .partial exists from the start

      RunControl control;
      control.quiet = options.quiet;
      control.progress_seconds = options.progress_seconds;
      control.progress_file = progress_path_for(options.output_path);
      control.checkpoint = options.checkpoint;
      control.restart_path = restart_path;
      control.resume = resume.get();
      control.add_run_state = [&](io::StateArchive& a) {
        put_identity(a, identity);
        a.put_number("run.wall_seconds", wall_before + elapsed());
        a.put_integer("run.restarts", restarts);
        a.put_integer("run.threads", threads);
        a.put_text("run.started", started);
      };

      try {
        status = scene.dim == 2 ? run_simulation2d(scene, out, control) : run_simulation3d(scene, out, control);
      } catch (const RestartRefused&) {
        throw;
      } catch (const std::exception& e) {
        if (const std::string cause = exhausted_resource(e); !cause.empty()) throw ResourcesExhausted{cause + ": " + e.what()};
        status = std::string("stopped: ") + e.what();
      }
    };
    std::unique_ptr<io::MemberWriter> out = std::make_unique<io::MemberWriter>(options.output_path);
    try {
      try {
        attempt(*out);
      } catch (const RestartRefused& e) {
        std::cerr << "capsule: restart point " << restart_path << " refused: " << e.what() << "; starting afresh\n";
        std::error_code ec;
        std::filesystem::remove(restart_path, ec);
        resume.reset();
        wall_before = 0, restarts = 0, started = utc_now();
        out = std::make_unique<io::MemberWriter>(options.output_path);
        attempt(*out);
      }
    } catch (const SimulatedKill& k) {
      std::cerr << "capsule: stopped at step " << k.step
                << " as asked (--stop-after-step); the .partial and the restart point are kept\n";
      return 1;
    } catch (const StoppedBySignal& s) {
      std::cerr << "capsule: stopped by signal " << s.signal << " at step " << s.step << "; "
                << (std::filesystem::exists(restart_path) ? "the restart point is written: the same command continues from it"
                                                          : "no restart point (healthy state unknown): the member starts afresh")
                << "\n";
      return kExitStoppedBySignal;
    }
    resume.reset();
    out->set_attribute("finished", utc_now());
    out->set_attribute("wall_seconds", wall_before + elapsed());
    out->finish(status);
    std::error_code ec;
    std::filesystem::remove(restart_path, ec);  // the member has ended: nothing to resume
    std::filesystem::remove(progress_path_for(options.output_path), ec);
    if (!options.quiet || status != "complete") std::cerr << "capsule: " << options.output_path << ": " << status << "\n";
    if (status == "complete") return 0;
    if (status.rfind("unstable", 0) == 0) return 3;
    return 1;
  } catch (const io::OwnershipLost& lost) {
    std::cerr << "capsule: " << lost.why << "; it stops here and leaves the member's files to their owner\n";
    return kExitOwnershipLost;
  } catch (const ResourcesExhausted& r) {
    std::cerr << "capsule: interrupted, " << r.why << "; the .partial and the last whole restart point are kept: "
              << "the same command continues from it once there is room\n";
    end_interrupted();
  } catch (const std::exception& e) {
    if (const std::string cause = exhausted_resource(e); !cause.empty()) {
      std::cerr << "capsule: interrupted, " << cause << ": " << e.what()
                << "; the last whole restart point is kept: the same command continues from it once there is room\n";
      end_interrupted();
    }
    std::cerr << "capsule: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace capsule
