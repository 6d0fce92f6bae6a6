#pragma once
// The scene's `protocol` section: shear until a condition, then recover until a condition
// (docs/guide/scenes.md "Keys"; run by solver/run/protocol.hpp).
#include <optional>

#include "solver/scene/choices.hpp"
#include "solver/scene/stretch_load.hpp"

namespace capsule {

// One phase of the protocol. Shear: until time (kt), steady (D_xy range over the last
// window_kt below tolerance), theta (inclination reaches value, rad, from above: tumbling,
// Sec. 4.1.2), beta (phase angle of the tracked element reaches value: tank-treading,
// Sec. 4.1.1), counted from after_kt on. Recover: until time (kt) or settled (as steady).
// max_kt caps the phase.
struct PhaseSpec {
  StopCondition until = StopCondition::time;
  double kt = 0;            // duration for until time
  double value = 0;         // threshold for theta / beta
  double tolerance = 1e-3;  // absolute range of D_xy over window_kt for "steady" / "settled"
  double window_kt = 2.0;
  double max_kt = 50.0;
  // recover only, settled: the window is max(window_kt, window_fraction x the time since the
  // stop), so a slow, non-monotone recovery is not taken as settled at a turning point.
  double window_fraction = 0.5;
  double oscillatory_period_kt = 0;  // shear only: > 0 -> wall speed (H/2) k sin(pi t / T) (Sec. 5.2.2)
  // shear only, theta / beta: a crossing counts from this kt on, so the stop falls in the
  // steady tumbling or tank-treading the text stops in (Sec. 4.1), not in the start-up.
  double after_kt = 0;
};

struct SceneProtocol {
  PhaseSpec shear;  // with a stretch: the loading phase's rule (until time, or steady D_axial)
  PhaseSpec recover;
  // 3D: the optical-tweezers load (protocol.stretch, solver/scene/stretch_scene.hpp) in place of
  // the shear: walls at rest, the patches pulled until `shear`'s rule.
  std::optional<StretchLoad> stretch;
};

}  // namespace capsule
