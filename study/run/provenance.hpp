#pragma once
// Member files say which code made them (code_version, cmake/code_version.cmake). A build whose
// sources differ from every commit says "<describe>-dirty-<hash>": its members cannot be
// reproduced from any commit, so `study run` and `study export` refuse such a build unless
// the user passes --allow-dirty (recorded in run.json as "allow_dirty": true).
#include <stdexcept>
#include <string>

namespace capsule::study {

// Thrown when a dirty build would run members; `study` exits 2 (nothing was run).
struct DirtyBuild : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// True when the environment says STUDY_ALLOW_DIRTY=1: the same as --allow-dirty (the test
// suite sets it, since it builds from a working tree that may hold uncommitted changes).
bool allow_dirty_from_environment();

// True for a version from sources that differ from a commit, or one that git could not tell.
bool is_uncommitted_version(const std::string& code_version);

// Throws DirtyBuild naming the version and the way out, unless allow_dirty or the version is
// a commit's. `what` names the command ("study run", "study export").
void require_committed_build(const std::string& code_version, bool allow_dirty, const std::string& what);

}  // namespace capsule::study
