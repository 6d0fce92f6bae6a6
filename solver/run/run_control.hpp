#pragma once
// What a member run hands its driver besides the scene (solver/run/run_member.cpp builds it):
// progress reporting, restart-point policy and the restart point to continue from.
#include <functional>
#include <string>

#include "solver/io/state_archive.hpp"
#include "solver/run/checkpoint.hpp"

namespace capsule {

struct RunControl {
  bool quiet = false;
  double progress_seconds = 5;   // wall seconds between progress lines (and progress-file updates)
  std::string progress_file;     // "" = none
  CheckpointPolicy checkpoint{0, -1, -1};  // off unless the caller asks
  std::string restart_path;      // where restart points go ("" = none)
  // Adds the run's identity and counters (wall time so far, restarts) to a restart point.
  std::function<void(io::StateArchive&)> add_run_state;
  io::StateArchive* resume = nullptr;  // the restart point to continue from, or none
  // A rerun for shapes only (`capsule shapes`, solver/run/shape_rerun.hpp): the loop returns
  // kShapesWritten after the row that stores the last shape of scene.output.shapes_at_kt, and a restart
  // point of the member's own run is continued with this scene's shapes (the member's are dropped;
  // one past the first shape asked for is refused).
  bool stop_after_last_shape = false;
};

inline constexpr const char* kShapesWritten = "shapes written";

}  // namespace capsule
