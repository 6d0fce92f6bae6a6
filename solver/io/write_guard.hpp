#pragma once
// Whether this process may still write its member's files. `study run-member` holds the member's
// lock (study/state/member_lock.hpp) and hands capsule the lock file and its own token in the
// environment (CAPSULE_MEMBER_LOCK, CAPSULE_MEMBER_LOCK_TOKEN). A run that was stopped (SIGSTOP,
// a frozen node) for longer than the lock's staleness may find its member taken over by another
// host; before every rename into the member's names (the .partial, the restart point, the member
// file, the progress file) and every removal, the writer checks that the lock still holds its
// token and otherwise backs off without touching a file. Without the variables (capsule run by
// hand) every write is allowed.
#include <string>

namespace capsule::io {

// Thrown when the lock names another owner. Not a std::exception: no handler that turns a
// solver error into a "stopped" member file may catch it.
struct OwnershipLost {
  std::string why;
};

// Reads the two variables once; nothing to check when they are unset.
void guard_writes_from_environment();
// Throws OwnershipLost when the member's lock no longer holds this run's token; `what` names
// the write about to happen.
void require_ownership(const std::string& what);

}  // namespace capsule::io
