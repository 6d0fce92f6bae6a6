// Files written whole or not at all (solver/common/atomic_write.hpp): the new text under a
// temporary name, renamed; a failure, or a check before the rename that throws, leaves the old
// file and no temporary.
#include <catch2/catch.hpp>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

#include "solver/common/atomic_write.hpp"

namespace fs = std::filesystem;
using namespace capsule;

namespace {

std::string text_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t entries(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST_CASE("an atomic write replaces the file whole and leaves no temporary", "[common]") {
  const fs::path dir = fresh_dir("capsule_atomic_write");
  const fs::path file = dir / "run.json";
  write_file_atomically(file, "old\n");
  CHECK(text_of(file) == "old\n");
  write_file_atomically(file, std::string(100000, 'x'));
  CHECK(text_of(file) == std::string(100000, 'x'));
  replace_atomically(file.string(), [&](const std::string& temporary) {
    CHECK(temporary == temporary_path(file.string()));  // written beside, under this process's name
    CHECK(text_of(file) == std::string(100000, 'x'));  // the old file stays until the rename
    std::ofstream(temporary) << "new\n";
  });
  CHECK(text_of(file) == "new\n");
  CHECK(entries(dir) == 1);
  fs::remove_all(dir);
}

TEST_CASE("a failed atomic write leaves the old file intact and no temporary", "[common]") {
  const fs::path dir = fresh_dir("capsule_atomic_write_failure");
  const fs::path file = dir / "member.h5";
  write_file_atomically(file, "old\n");
  // A writer that fails half way with errno set (a full disk): the errno stays the cause.
  try {
    replace_atomically(file.string(), [](const std::string& temporary) {
      std::ofstream(temporary) << "half";
      errno = ENOSPC;
      throw std::runtime_error("cannot write the member file");
    });
    FAIL("no exception");
  } catch (const std::system_error& e) {
    CHECK(e.code() == std::errc::no_space_on_device);
  }
  CHECK(text_of(file) == "old\n");
  CHECK(entries(dir) == 1);
  // A rename that fails (the target is a folder holding a file): the folder and its file stay.
  const fs::path folder = dir / "folder";
  fs::create_directories(folder);
  write_file_atomically(folder / "inside", "kept\n");
  CHECK_THROWS_WITH(write_file_atomically(folder, "text\n"), Catch::Contains("cannot write") && Catch::Contains("renaming"));
  CHECK_THROWS_AS(replace_atomically(folder.string(), [](const std::string& t) { std::ofstream(t) << "x"; }),
                  fs::filesystem_error);
  CHECK(text_of(folder / "inside") == "kept\n");
  CHECK(entries(dir) == 2);  // the file and the folder: no temporary
  // A missing folder: the temporary cannot be created.
  CHECK_THROWS_WITH(write_file_atomically(dir / "missing" / "file", "x"), Catch::Contains("creating"));
  fs::remove_all(dir);
}

TEST_CASE("a check before the rename that throws leaves the old file and no temporary", "[common]") {
  const fs::path dir = fresh_dir("capsule_atomic_write_check");
  const fs::path file = dir / "member.h5.progress";
  write_file_atomically(file, "old\n");
  struct Refused {};  // not a std::exception, as the write guard's OwnershipLost
  bool asked = false;
  const auto refuse = [&] {
    CHECK(fs::exists(temporary_path(file.string())));  // asked once the temporary is whole
    asked = true;
    throw Refused{};
  };
  CHECK_THROWS_AS(write_file_atomically(file, "new\n", refuse), Refused);
  CHECK(asked);
  asked = false;
  CHECK_THROWS_AS(replace_atomically(file.string(), [](const std::string& t) { std::ofstream(t) << "new\n"; }, refuse),
                  Refused);
  CHECK(asked);
  CHECK(text_of(file) == "old\n");
  CHECK(entries(dir) == 1);
  write_file_atomically(file, "new\n", [] {});  // a check that passes
  CHECK(text_of(file) == "new\n");
  fs::remove_all(dir);
}
