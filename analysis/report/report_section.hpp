#pragma once
// One kind of analysis in a campaign's report (characteristic-time tables, bilinear fit,
// slices, resolution ladder, ...): write_report walks a list of sections in order, and
// each writes its own files and its part of fits.json and figure_data.json.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/report/report_context.hpp"
#include "analysis/report/table.hpp"

namespace capsule::analysis {

struct ReportOutputs {
  nlohmann::json fits = nlohmann::json::object();         // fits.json
  nlohmann::json figure_data = nlohmann::json::object();  // figures/figure_data.json (drawn if figures are on)
  std::vector<std::string> files;                         // every file written, in order

  // <dir>/<stem>.md, .csv, .tex
  void write_table(const Table& table, const std::filesystem::path& dir, const std::string& stem);
  void write_text(const std::filesystem::path& path, const std::string& text);
};

class ReportSection {
 public:
  virtual ~ReportSection() = default;
  virtual void write(const ReportContext& context, const std::filesystem::path& out_dir,
                     ReportOutputs& outputs) const = 0;
};

// The sections of a report, in the order write_report walks them (each in its own file).
std::unique_ptr<ReportSection> member_fits_section();          // member_fits_section.cpp
std::unique_ptr<ReportSection> slices_section();               // slices_section.cpp
std::unique_ptr<ReportSection> time_tables_section();          // time_tables_section.cpp
std::unique_ptr<ReportSection> bilinear_section();             // bilinear_section.cpp
std::unique_ptr<ReportSection> artificial_viscosity_section(); // artificial_viscosity_section.cpp
std::unique_ptr<ReportSection> ladder_section();               // ladder_section.cpp
std::unique_ptr<ReportSection> accuracy_section();             // accuracy_section.cpp
std::unique_ptr<ReportSection> stability_section();            // stability_section.cpp
std::unique_ptr<ReportSection> published_section();            // published_section.cpp
std::unique_ptr<ReportSection> experiment_section();           // experiment_section.cpp

}  // namespace capsule::analysis
