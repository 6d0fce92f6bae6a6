#pragma once
// Runs one scene from start to end and writes its member file.
#include <string>

namespace capsule {

struct RunOptions {
  std::string scene_path;
  std::string output_path;
  int threads = 0;        // 0: leave OpenMP's default
  std::string member_id;  // recorded in the member file; study passes the hash
  bool quiet = false;
};

// Exit codes: 0 complete, 3 unstable, 2 bad scene or usage, 1 other failure.
int run_member(const RunOptions& options);

}  // namespace capsule
