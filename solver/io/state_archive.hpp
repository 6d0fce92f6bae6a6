#pragma once
// A restart point on disk: a flat set of named arrays (float64, int64) and texts in one HDF5
// file (docs/guide/running.md "Checkpoints"). What the names mean is decided by the parts that save their
// state (solver/run/checkpoint.hpp); this file only stores and reloads them exactly: doubles
// are written as IEEE float64 and come back bit for bit (NaN included).
//
// Names are dotted ("fluid.populations", "protocol.kt"); each becomes one dataset at the
// file's root. write() is atomic (solver/common/atomic_write.hpp): written under a temporary name, renamed.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace capsule::io {

class StateArchive {
 public:
  void put(const std::string& name, std::vector<double> values) { doubles_[name] = std::move(values); }
  void put(const std::string& name, std::vector<std::int64_t> values) { ints_[name] = std::move(values); }
  void put_number(const std::string& name, double value) { doubles_[name] = {value}; }
  void put_integer(const std::string& name, std::int64_t value) { ints_[name] = {value}; }
  void put_text(const std::string& name, std::string text) { texts_[name] = std::move(text); }

  bool has(const std::string& name) const {
    return doubles_.count(name) || ints_.count(name) || texts_.count(name);
  }
  // Each throws std::runtime_error("restart point has no <name>") when absent or of another kind.
  const std::vector<double>& doubles(const std::string& name) const;
  const std::vector<std::int64_t>& ints(const std::string& name) const;
  const std::string& text(const std::string& name) const;
  double number(const std::string& name) const;        // a one-element doubles
  std::int64_t integer(const std::string& name) const;  // a one-element ints

  // Moves an array out (large fields: the fluid's populations), leaving it empty here.
  std::vector<double> take_doubles(const std::string& name);

  std::size_t payload_bytes() const;  // 8 bytes per number plus the texts

  void write(const std::string& path) const;
  // Throws std::runtime_error naming the file when it is missing or not a restart point.
  static StateArchive read(const std::string& path);

 private:
  std::map<std::string, std::vector<double>> doubles_;
  std::map<std::string, std::vector<std::int64_t>> ints_;
  std::map<std::string, std::string> texts_;
};

}  // namespace capsule::io
