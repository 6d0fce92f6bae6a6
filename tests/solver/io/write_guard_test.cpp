// A writer whose member lock was taken over renames nothing into the member's names and leaves
// no temporary behind (solver/io/write_guard.hpp).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "solver/io/member_file.hpp"
#include "solver/io/state_archive.hpp"
#include "solver/io/write_guard.hpp"

namespace fs = std::filesystem;
using namespace capsule::io;

namespace {

void write_lock(const fs::path& file, const std::string& token) {
  std::ofstream(file) << R"({"host": "h", "pid": 1, "started": "x", "token": ")" << token << "\"}\n";
}

std::string text_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("a writer that lost the member's lock renames nothing over the new owner's files", "[io]") {
  const fs::path dir = fs::temp_directory_path() / ("capsule_write_guard_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path lock = dir / "member.lock", restart = dir / "member.h5.restart";
  write_lock(lock, "mine");
  ::setenv("CAPSULE_MEMBER_LOCK", lock.c_str(), 1);
  ::setenv("CAPSULE_MEMBER_LOCK_TOKEN", "mine", 1);
  guard_writes_from_environment();

  StateArchive a;
  a.put("x", std::vector<double>{1, 2, 3});
  a.write(restart.string());  // still the owner: written
  MemberWriter out((dir / "member.h5").string());
  out.set_attribute("member_id", "m");
  out.checkpoint();
  const std::string restart_before = text_of(restart), partial_before = text_of(out.partial_path());

  write_lock(lock, "theirs");  // taken over
  StateArchive b;
  b.put("x", std::vector<double>{4, 5, 6});
  CHECK_THROWS_AS(b.write(restart.string()), OwnershipLost);
  CHECK_THROWS_AS(out.checkpoint(), OwnershipLost);
  CHECK_THROWS_AS(out.finish("complete"), OwnershipLost);
  CHECK(text_of(restart) == restart_before);
  CHECK(text_of(out.partial_path()) == partial_before);
  CHECK_FALSE(fs::exists(dir / "member.h5"));
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  CHECK(files == 3);  // the lock, the restart point, the .partial: no temporary left

  ::unsetenv("CAPSULE_MEMBER_LOCK");
  ::unsetenv("CAPSULE_MEMBER_LOCK_TOKEN");
  guard_writes_from_environment();
  fs::remove_all(dir);
}
