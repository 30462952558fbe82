// results.csv round trip: every field back exactly, quoting, unknown errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "shared/common/error.hpp"
#include "shared/compare/results_table.hpp"
#include "shared/compare/run_record.hpp"

namespace altfem {
namespace {

TEST(ResultsTable, RoundTripsEveryFieldExactly) {
  RunRecord ok;
  ok.hash = "0123456789abcdef";
  ok.method = "fem";
  ok.element = "hex20";
  ok.label = "fem element=hex20 resolution=[10,1,1]";
  ok.overrides = "discretization/fem/resolution=[10,1,1]";
  ok.is_reference = true;
  ok.status = "ok";
  ok.dofs = 1863;
  ok.elements = 40;
  ok.quadrature_points = 1080;
  ok.steps = 1;
  ok.newton_iterations = 2;
  ok.linear_iterations = 7;
  ok.timings = {0.1, 0.2, 1.0 / 3.0, 0.4, 0.5, 0.6, 2.1};
  ok.events = 2;
  ok.refinements = 1;
  ok.event_geometry_seconds = 1.0 / 9.0;
  ok.event_integration_seconds = 0.25;
  ok.event_pattern_seconds = 0.125;
  ok.event_transfer_seconds = 1e-5;
  ok.wall_seconds = 2.25;
  ok.peak_memory_mib = 28.5;
  ok.rms_error = 1.2345678901234567e-7;
  ok.max_error = 3e-6;
  ok.relative_rms_error = 0.1 / 3.0;
  ok.field_l2_error = 2.5e-4;
  ok.field_h1_error = 1.0 / 7.0;
  ok.scene = "cantilever";
  ok.date = "2026-11-23 07:00 UTC";
  ok.cpu = "AMD EPYC, \"quoted\"";
  ok.cores = 2;
  ok.threads = 2;
  ok.blas = "OpenBLAS 0.3.21";
  RunRecord failed = ok;
  failed.is_reference = false;
  failed.status = "invalid input";
  failed.exit_code = 2;
  failed.message = "scene.json: /discretization/fem/resolution: expected an array of 3 integers, got \"bad\"\nsecond";
  failed.rms_error = std::numeric_limits<double>::quiet_NaN();
  failed.max_error = std::numeric_limits<double>::quiet_NaN();

  const auto file = std::filesystem::temp_directory_path() / "altfem_unit_results.csv";
  write_results_csv(file, {ok, failed});
  const auto read = read_results_csv(file);
  ASSERT_EQ(read.size(), 2u);
  for (const auto& [written, back] : {std::pair{ok, read[0]}, std::pair{failed, read[1]}}) {
    EXPECT_EQ(back.hash, written.hash);
    EXPECT_EQ(back.label, written.label);
    EXPECT_EQ(back.overrides, written.overrides);
    EXPECT_EQ(back.is_reference, written.is_reference);
    EXPECT_EQ(back.status, written.status);
    EXPECT_EQ(back.exit_code, written.exit_code);
    EXPECT_EQ(back.message, written.message);
    EXPECT_EQ(back.dofs, written.dofs);
    EXPECT_EQ(back.linear_iterations, written.linear_iterations);
    EXPECT_EQ(back.timings.assembly, written.timings.assembly);  // 17 digits: exact
    EXPECT_EQ(back.timings.total, written.timings.total);
    EXPECT_EQ(back.peak_memory_mib, written.peak_memory_mib);
    EXPECT_EQ(back.cpu, written.cpu);
    EXPECT_EQ(back.threads, written.threads);
  }
  EXPECT_EQ(read[0].rms_error, ok.rms_error);
  EXPECT_EQ(read[0].relative_rms_error, ok.relative_rms_error);
  EXPECT_EQ(read[0].field_l2_error, ok.field_l2_error);
  EXPECT_EQ(read[0].field_h1_error, ok.field_h1_error);
  EXPECT_EQ(read[0].events, 2);
  EXPECT_EQ(read[0].refinements, 1);
  EXPECT_EQ(read[0].event_geometry_seconds, ok.event_geometry_seconds);
  EXPECT_EQ(read[0].event_transfer_seconds, ok.event_transfer_seconds);
  EXPECT_TRUE(std::isnan(read[1].rms_error));
  std::filesystem::remove(file);
}

// The events of a run's summary.json: counted (the refine ones apart: they make the run
// adaptive), and their seconds per phase summed.
TEST(ResultsTable, AddsUpTheEventsOfASummary) {
  const auto event = [](double geometry, double integration, double pattern, double transfer) {
    return nlohmann::json{
        {"kind", geometry > 0.3 ? "cut" : "refine"},
        {"seconds",
         {{"geometry", geometry}, {"integration", integration}, {"pattern", pattern}, {"transfer", transfer}}}};
  };
  nlohmann::json summary = {{"dofs", 10},
                            {"elements", {{"hex20", 2}}},
                            {"quadrature_points", 54},
                            {"steps", 3},
                            {"newton_iterations", 3},
                            {"linear_iterations", 0},
                            {"timings_s",
                             {{"setup", 0.1},
                              {"quadrature", 0.1},
                              {"assembly", 0.1},
                              {"analysis", 0.1},
                              {"factorisation", 0.1},
                              {"solve", 0.1},
                              {"total", 0.6}}},
                            {"events", {event(0.5, 1.0, 0.25, 0.125), event(0.25, 2.0, 0.5, 0.375)}}};
  RunRecord record;
  add_summary(record, summary);
  EXPECT_EQ(record.events, 2);
  EXPECT_EQ(record.refinements, 1);
  EXPECT_EQ(record.event_geometry_seconds, 0.75);
  EXPECT_EQ(record.event_integration_seconds, 3.0);
  EXPECT_EQ(record.event_pattern_seconds, 0.75);
  EXPECT_EQ(record.event_transfer_seconds, 0.5);
  summary.erase("events");
  add_summary(record, summary);
  EXPECT_EQ(record.events, 0);
  EXPECT_EQ(record.refinements, 0);
  EXPECT_EQ(record.event_integration_seconds, 0.0);
}

// A run cached before `refinements` was a column (runs/<hash>/record.csv) still reads, as
// a run that did not refine.
TEST(ResultsTable, ReadsACachedRecordWithoutTheRefinementsColumn) {
  RunRecord record;
  record.method = "fem";
  record.refinements = 3;
  const auto file = std::filesystem::temp_directory_path() / "altfem_unit_results_older.csv";
  write_results_csv(file, {record});
  std::ifstream in(file);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  in.close();
  // No field of this record holds a comma: drop the column by position.
  const auto drop = [](const std::string& line, std::size_t column) {
    std::vector<std::string> fields{""};  // empty fields kept, the last one too
    for (const char c : line)
      if (c == ',') fields.emplace_back();
      else fields.back() += c;
    fields.erase(fields.begin() + static_cast<std::ptrdiff_t>(column));
    std::string joined;
    for (std::size_t k = 0; k < fields.size(); ++k) joined += (k ? "," : "") + fields[k];
    return joined;
  };
  std::stringstream names(header);
  std::size_t column = 0;
  for (std::string name; std::getline(names, name, ',') && name != "refinements";) ++column;
  std::ofstream(file) << drop(header, column) << "\n" << drop(row, column) << "\n";
  const std::vector<RunRecord> read = read_results_csv(file);
  ASSERT_EQ(read.size(), 1u);
  EXPECT_EQ(read[0].method, "fem");
  EXPECT_EQ(read[0].refinements, 0);
  std::filesystem::remove(file);
}

TEST(ResultsTable, RejectsMissingColumnsAndBadNumbers) {
  const auto file = std::filesystem::temp_directory_path() / "altfem_unit_results_bad.csv";
  std::ofstream(file) << "hash,method\nabc,fem\n";
  EXPECT_THROW(read_results_csv(file), InputError);
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace altfem
