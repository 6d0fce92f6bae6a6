#pragma once
// Runs a 3D scene in this process into a temporary member file and reads it back (the file is
// removed): the solver's output as the member file holds it, for the 3D run tests.
#include <filesystem>
#include <string>

#include "solver/io/member_file.hpp"
#include "solver/run/simulation3d.hpp"
#include "solver/scene/scene.hpp"

namespace capsule::testing {

inline io::MemberData run_scene3d(const Scene& scene, const std::string& file_stem) {
  const std::string path = (std::filesystem::temp_directory_path() / (file_stem + ".h5")).string();
  {
    io::MemberWriter out(path);
    const std::string status = run_simulation3d(scene, out, true);
    out.finish(status);
  }
  io::MemberData d = io::read_member(path);
  std::filesystem::remove(path);
  return d;
}

}  // namespace capsule::testing
