#pragma once
// The matplotlib script that draws the report's figures (analysis/report/plot_report.py),
// embedded at build time so that the report does not depend on where the source tree is. It
// reads figures/figure_data.json.
#include <string>

namespace capsule::analysis {

const std::string& plot_script_text();

// Runs `<python> <script> <data> <out_dir>` if that interpreter exists and has matplotlib.
// Returns "" on success, else why the figures were skipped.
std::string run_plot_script(const std::string& script_path, const std::string& data_path, const std::string& out_dir,
                            const std::string& python = "/usr/bin/python3");

}  // namespace capsule::analysis
