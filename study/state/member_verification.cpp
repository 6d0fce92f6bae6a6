#include "study/state/member_verification.hpp"

#include <sys/stat.h>

#include <string>

#include "solver/io/member_file.hpp"
#include "study/state/results_layout.hpp"

namespace capsule::study {

namespace fs = std::filesystem;

namespace {

// What identifies one version of the file: size, modification and change times, content hash. The
// change time moves on every write, also one that sets the modification time back.
std::string fingerprint(const fs::path& h5, const std::string& recorded_hash) {
  struct stat st {};
  if (::stat(h5.c_str(), &st) != 0) return "";
  return "size " + std::to_string(st.st_size) + " mtime " + std::to_string(st.st_mtim.tv_sec) + "." +
         std::to_string(st.st_mtim.tv_nsec) + " ctime " + std::to_string(st.st_ctim.tv_sec) + "." +
         std::to_string(st.st_ctim.tv_nsec) + " content_hash " + recorded_hash + "\n";
}

}  // namespace

fs::path verification_record(const fs::path& h5) { return h5.string() + ".verified"; }

std::string verify_member_file(const fs::path& h5, const std::string& recorded_hash) {
  const std::string before = fingerprint(h5, recorded_hash);
  if (!before.empty() && !recorded_hash.empty() && read_file_text(verification_record(h5)) == before) return "";
  std::string hash;
  try {
    hash = io::read_member(h5.string()).attributes.value(io::kContentHashAttribute, std::string());
  } catch (const std::exception& e) {
    std::error_code ec;
    fs::remove(verification_record(h5), ec);
    return e.what();
  }
  // Recorded (with the hash the file holds) only when the file did not change while it was read.
  const std::string after = fingerprint(h5, hash);
  if (!hash.empty() && !after.empty() && after == fingerprint(h5, recorded_hash) && after == before) {
    try {
      write_file_atomically(verification_record(h5), after);
    } catch (const std::exception&) {
      // a read-only folder: verified again next time
    }
  }
  return "";
}

}  // namespace capsule::study
