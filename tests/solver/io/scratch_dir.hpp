#pragma once
// Test helper: an empty folder of its own under the temporary directory, named by test and pid.
#include <filesystem>
#include <string>
#include <unistd.h>

namespace capsule::io::testing {

inline std::filesystem::path fresh_dir(const std::string& name) {
  const std::filesystem::path d =
      std::filesystem::temp_directory_path() / ("capsule_io_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

}  // namespace capsule::io::testing
