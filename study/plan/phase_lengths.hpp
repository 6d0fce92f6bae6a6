#pragma once
// How long a phase that ends on a condition (shear until steady, recovery until settled) will
// run, from the members that have run: the complete member files under a results folder record
// their scene and their phase ends (markers t_stop, t_end). A member that has not run is
// expected to run as long as its nearest finished neighbours with the same stopping rule
// (docs/guide/running.md "Time and memory estimates"). Measured on the shipped results
// (docs/findings/performance.md "Time estimates against measured runs"), this is several times
// closer than one fixed length: a capsule with a viscous membrane or inner fluid takes longer
// to steady, and a recovery of a membrane power law runs to its cap.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

namespace capsule::study {

class PhaseLengths {
 public:
  // One finished member: its canonical scene and how long each phase ran (kt).
  void add(const nlohmann::json& scene, double shear_kt, double recover_kt);
  // Every complete member file under results_dir/<campaign>/members/<member>/member.h5; files
  // that cannot be read, or lack a scene or markers, are left out.
  static PhaseLengths from_results(const std::filesystem::path& results_dir);

  // The expected length (kt) of the scene's shear (recovery = false) or recovery phase when it
  // ends on a condition and finished members with the same rule (until, window, tolerance)
  // exist: the weighted geometric mean of its three nearest neighbours' lengths, never past
  // its own cap. Empty otherwise.
  std::optional<double> expected_kt(const nlohmann::json& scene, bool recovery) const;

  std::size_t size() const { return records_.size(); }

 private:
  struct Record {
    nlohmann::json scene;
    double kt[2];  // shear, recovery
  };
  std::vector<Record> records_;
};

}  // namespace capsule::study
