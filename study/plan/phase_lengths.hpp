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
#include <string>
#include <vector>

namespace capsule::study {

class PhaseLengths {
 public:
  // One finished member: its canonical scene and how long each phase ran (kt).
  void add(const nlohmann::json& scene, double shear_kt, double recover_kt);
  // Every complete member file under results_dir/<campaign>/members/<member>/member.h5; files
  // that cannot be read, or lack a scene or markers, are left out.
  static PhaseLengths from_results(const std::filesystem::path& results_dir);
  // The toolkit's own shipped members, built in (shipped_phase_lengths.hpp): what a results
  // folder without finished neighbours is expected from.
  static const PhaseLengths& shipped();
  // Adds the records of `other` that this one does not hold already (the same physics and
  // lengths: a shipped member also found under the results folder counts once).
  void merge(const PhaseLengths& other);
  // What the planner expects from: the finished members under results_dir, then the shipped
  // members it does not hold.
  static PhaseLengths known(const std::filesystem::path& results_dir);

  // The expected length (kt) of the scene's first phase (recovery = false: the shear, or a stretch's loading) or recovery phase when it
  // ends on a condition and finished members with the same rule (until, window, tolerance)
  // exist: the weighted geometric mean of its three nearest neighbours' lengths, never past
  // its own cap. Empty otherwise.
  std::optional<double> expected_kt(const nlohmann::json& scene, bool recovery) const;

  std::size_t size() const { return records_.size(); }
  // The same records, in any order.
  bool same_records(const PhaseLengths& other) const;

 private:
  // A member's physics as the distance reads it, and its stopping rules ("until window
  // tolerance" of shear and recovery), computed once when the member is added.
  struct Physics {
    int dim = 0;
    double log_Ca = 0, log_V = 0, eta = 0, E_b = 0, power_n = 1, power_K = 0, G = 0, c0 = 0;
    std::string shape, law, reference_case, sls_reading;
    std::string rule[2];
    bool operator==(const Physics& o) const;
  };
  struct Record {
    Physics physics;
    double kt[2];  // shear, recovery
  };
  static Physics physics_of(const nlohmann::json& scene);
  static double distance(const Physics& a, const Physics& b);
  std::vector<Record> records_;
};

}  // namespace capsule::study
