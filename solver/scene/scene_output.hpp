#pragma once
// The scene's `output` section: the spacing of the member file's rows and what else it holds
// (docs/guide/member-files.md).
#include <vector>

#include "solver/scene/choices.hpp"

namespace capsule {

struct SceneOutput {
  double interval_kt = 0.05;         // one series row per interval; the protocol's stop tests read them
  std::vector<double> shapes_at_kt;  // membrane shapes stored at these times
  Snapshots snapshots = Snapshots::none;
};

}  // namespace capsule
