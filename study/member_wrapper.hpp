#pragma once
// The generated script GNU Parallel (or a Slurm task) runs for one member:
//   run_member.sh MEMBER_DIR THREADS
// It runs `capsule MEMBER_DIR/scene.json -o MEMBER_DIR/member.h5 --id ID --threads THREADS`
// (ID = the 16 hex digits after the directory name's last '-'), appends the capsule's
// progress lines and messages to MEMBER_DIR/capsule.log and keeps its exit status in
// MEMBER_DIR/exit_status. A member killed earlier continues from its restart point.
// Arguments arrive as positional parameters and are always quoted: nothing is interpolated.
#include <filesystem>
#include <string>

namespace capsule::study {

std::string member_wrapper_text(const std::filesystem::path& capsule_binary, const std::string& campaign_name);

// Writes the wrapper (mode 0755) atomically.
void write_member_wrapper(const std::filesystem::path& path, const std::filesystem::path& capsule_binary,
                          const std::string& campaign_name);

}  // namespace capsule::study
