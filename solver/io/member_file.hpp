#pragma once
// One HDF5 file per member (docs/CONTRACTS.md "Member file", docs/guide/member-files.md "Layout").
// Written to <path>.partial and renamed to <path> when the member ends, so a killed
// run never leaves a file that looks finished.
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>
#include <vector>

#include "solver/io/state_archive.hpp"

namespace capsule::io {

// The root attribute holding the file's content hash (content_hash.hpp) over every attribute
// and dataset; read_member recomputes it and refuses a file whose content changed.
inline constexpr const char* kContentHashAttribute = "content_hash";

class MemberWriter {
 public:
  explicit MemberWriter(std::string final_path);
  MemberWriter(const MemberWriter&) = delete;
  MemberWriter& operator=(const MemberWriter&) = delete;

  void set_attribute(const std::string& name, const std::string& value);
  void set_attribute(const std::string& name, const char* value) { set_attribute(name, std::string(value)); }
  void set_attribute(const std::string& name, double value);
  void set_attribute(const std::string& name, long value);
  void set_attribute(const std::string& name, int value) { set_attribute(name, static_cast<long>(value)); }
  void set_scene(const nlohmann::json& scene);  // attribute "scene", canonical JSON text

  // One output row; every row carries the same keys (the first row fixes them).
  void append(const std::map<std::string, double>& row, const std::vector<double>& beta = {});
  void set_markers(const std::map<std::string, double>& markers);
  void add_shape(double kt, const std::vector<double>& xyz, int dim, const std::vector<int>& triangles = {});

  std::size_t rows() const { return rows_; }
  const std::map<std::string, std::vector<double>>& series() const { return series_; }
  const std::vector<std::vector<double>>& beta() const { return beta_; }
  void clear_shapes() { shapes_.clear(); }
  std::vector<double> shape_times() const;  // the kt of each shape held
  const std::map<std::string, std::variant<std::string, double, long>>& attributes() const { return attributes_; }
  const std::string& final_path() const { return final_path_; }
  std::string partial_path() const { return final_path_ + ".partial"; }

  void checkpoint();                       // rewrite <path>.partial, status "running"
  void finish(const std::string& status);  // write status, rename .partial -> final
  // No .partial: checkpoint() writes nothing (a rerun whose rows are only compared, `capsule shapes`).
  void hold_in_memory() { in_memory_ = true; }
  // The shape file of `capsule shapes` (docs/guide/member-files.md "Shapes of a finished member"):
  // the root attributes with status "shapes" and /shapes as a member file lays them out, no
  // series and no markers; written atomically to `path`, content hash included (read_member reads it).
  void write_shapes_file(const std::string& path) const;

  // Restart points (solver/run/checkpoint.hpp): the rows, tracked angles and shapes written
  // so far, under names "member.*". Attributes are not saved: the run sets them again.
  void save_rows(StateArchive& archive) const;
  void restore_rows(const StateArchive& archive);  // replaces what this writer holds

 private:
  void write(const std::string& path, const std::string& status, bool with_rows = true) const;
  void write_then_rename(const std::string& status, const std::string& to) const;

  std::string final_path_;
  std::map<std::string, std::variant<std::string, double, long>> attributes_;
  std::vector<std::string> columns_;
  std::map<std::string, std::vector<double>> series_;
  std::vector<std::vector<double>> beta_;
  std::map<std::string, double> markers_;
  struct Shape {
    double kt;
    std::vector<double> xyz;
    int dim;
  };
  std::vector<Shape> shapes_;
  std::vector<int> triangles_;
  std::size_t rows_ = 0;
  bool in_memory_ = false;
};

struct MemberData {
  std::string path;
  std::string status;                 // complete | unstable at kt = X: reason | stopped: reason | running
  nlohmann::json attributes;          // every root attribute; "scene" parsed into JSON
  std::map<std::string, std::vector<double>> series;
  std::vector<std::vector<double>> beta;  // rows x tracked elements
  std::map<std::string, double> markers;  // NaN where not reached
  struct Shape {
    double kt;
    int dim;
    std::vector<double> xyz;
  };
  std::vector<Shape> shapes;
  std::vector<int> triangles;
  bool complete() const { return status == "complete"; }
  bool unstable() const { return status.rfind("unstable", 0) == 0; }
};

// Reads a member file (final or .partial). Throws std::runtime_error naming the file, also
// when a dataset's checksum or the file's content hash does not match (the file was damaged),
// and when the file has no content hash at all (one whose hash was deleted reads like a file
// from before hashes existed), unless legacy files were accepted below.
MemberData read_member(const std::string& path);

// Accept member files without a content hash (written before it existed), for the rest of this
// process; `study report --legacy-member-files` asks for it. Off by default.
void accept_files_without_content_hash(bool accept);

// What is wrong with a complete member's series, "" when nothing: every member writes kt and
// D_xy (what every analysis reads), and every series has one row per output time. A file from before the content
// hash can lose a dataset unnoticed by read_member; this catches that.
std::string missing_series(const MemberData& member);

// Status and member id only, cheaply (for planners deciding what to rerun).
struct MemberStatus {
  std::string status;
  std::string member_id;
  // What the run measured (NaN / 0 when absent): for the planner's speed calibration.
  double wall_seconds = std::numeric_limits<double>::quiet_NaN();
  double steps = std::numeric_limits<double>::quiet_NaN();
  long threads = 0;
  // Provenance: the build that wrote it (a `-dirty` one is not reproducible) and its physics.
  std::string code_version, physics_version;
  std::string content_hash;  // as recorded ("" when none); read_member checks it against the content
  // The fluid's relaxation time the member ran with (the scene's, or the rule's when it is 0).
  double tau = std::numeric_limits<double>::quiet_NaN();
  // How long its phases ran (markers t_stop and t_end, NaN when absent), and its canonical scene
  // (null when absent): for the planner's expected phase lengths.
  double t_stop = std::numeric_limits<double>::quiet_NaN();
  double t_end = std::numeric_limits<double>::quiet_NaN();
  nlohmann::json scene;
};
MemberStatus read_member_status(const std::string& path);

}  // namespace capsule::io
