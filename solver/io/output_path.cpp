#include "solver/io/output_path.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace capsule::io {

namespace fs = std::filesystem;

std::string output_path_problem(const std::string& path) {
  if (path.empty()) return "the output path (-o) is empty";
  std::error_code ec;
  const fs::path p(path);
  if (fs::is_directory(p, ec)) return path + ": is a folder (-o names the member file to write, e.g. member.h5)";
  if (fs::is_directory(path + ".partial", ec)) return path + ".partial: is a folder";
  const fs::path parent = fs::absolute(p, ec).parent_path();
  if (!fs::exists(parent, ec)) return path + ": the folder " + parent.string() + " does not exist";
  if (!fs::is_directory(parent, ec)) return path + ": " + parent.string() + " is not a folder";
  if (::access(parent.c_str(), W_OK | X_OK) != 0)
    return path + ": cannot write in the folder " + parent.string() + ": " + std::strerror(errno);
  return "";
}

}  // namespace capsule::io
