#pragma once
// Before any command says a member is complete, its member file is read whole: every dataset's
// checksum and the file's content hash (solver/io/member_file.hpp). The root attributes alone
// (status, member_id) can be edited with the hash kept, or sit on a damaged dataset.
//
// Reading every file whole at each `study status` would make a status of 10^5 members slow, so
// a verified file is remembered in <member>/member.h5.verified: its size, modification and change
// times (nanoseconds) and content hash. A file whose size, times or hash differ from the record
// is read whole again. The record is best effort: a folder that cannot be written keeps none.
#include <filesystem>
#include <string>

namespace capsule::study {

// "" when the member file at h5 reads whole (checksums and content hash match), else why not.
// recorded_hash is the file's content_hash attribute as read cheaply (read_member_status).
std::string verify_member_file(const std::filesystem::path& h5, const std::string& recorded_hash);

std::filesystem::path verification_record(const std::filesystem::path& h5);  // <h5>.verified

}  // namespace capsule::study
