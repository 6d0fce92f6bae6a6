#pragma once
// Files written whole or not at all: under this process's temporary name beside the target
// (temporary_path), then renamed over it, so a reader sees the old file or the new one, never a
// part. A failure removes the temporary and leaves the old file as it was. `before_rename`, when
// given, is the last check before the rename (the member's write guard, solver/io/write_guard.hpp);
// when it throws, the temporary is removed and its exception propagates. No fsync: the rename is
// atomic for other processes, not across a power cut.
#include <filesystem>
#include <functional>
#include <string>

namespace capsule {

// <path>.tmp.<pid>: beside the target (same file system, so the rename is atomic) and used by no
// other process.
std::string temporary_path(const std::string& path);

// Writes `text` to `path`; std::runtime_error naming the path, the step (creating, writing,
// closing, renaming), the temporary and errno's reason (disk full, read-only, no permission).
void write_file_atomically(const std::filesystem::path& path, const std::string& text,
                           const std::function<void()>& before_rename = {});

// Writes `path` by `write`, which creates and fills the file it is handed (the temporary: an
// HDF5 file, a stream). A std::runtime_error from `write` with errno set comes out as a
// std::system_error carrying that errno (a full disk stays ENOSPC); a failed rename as a
// std::filesystem::filesystem_error.
void replace_atomically(const std::string& path, const std::function<void(const std::string& temporary)>& write,
                        const std::function<void()>& before_rename = {});

}  // namespace capsule
