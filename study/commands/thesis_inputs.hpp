#pragma once
// What `study thesis` reads, checked before it reads it: each campaign's report/fits.json must
// be the one `study report` wrote (its hash in fits.json.hash, written beside it) and no newer
// than the member files it fitted.
#include <filesystem>
#include <string>
#include <vector>

namespace capsule::study {

// "fits.json.hash": the FNV-1a 64 hash of fits.json's bytes, in hex, written by `study report`.
std::string fits_hash_text(const std::string& fits_json_bytes);
void write_fits_hash(const std::filesystem::path& report_dir);

// One warning per campaign under results_dir whose report was edited since `study report`
// wrote it or is older than one of its member files, naming the campaign and the command that
// writes the report again.
std::vector<std::string> thesis_input_warnings(const std::filesystem::path& results_dir);

}  // namespace capsule::study
