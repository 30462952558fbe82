#include "shared/compare/results_table.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <variant>

#include "shared/common/error.hpp"
#include "shared/io/atomic_file.hpp"

namespace altfem {

namespace {

std::string number_text(double value) {
  if (std::isnan(value)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

std::string quoted(const std::string& field) {
  if (field.find_first_of(",\"\n\r") == std::string::npos) return field;
  std::string text = "\"";
  for (const char c : field) text += c == '"' ? std::string("\"\"") : std::string(1, c);
  return text + "\"";
}

// Each column of results.csv and the RunRecord member it holds.
using Member = std::variant<std::string RunRecord::*, bool RunRecord::*, int RunRecord::*, long long RunRecord::*,
                            double RunRecord::*, double PhaseTimings::*>;

const std::vector<std::pair<std::string, Member>>& columns() {
  static const std::vector<std::pair<std::string, Member>> table{
      {"hash", &RunRecord::hash},
      {"method", &RunRecord::method},
      {"element", &RunRecord::element},
      {"label", &RunRecord::label},
      {"overrides", &RunRecord::overrides},
      {"is_reference", &RunRecord::is_reference},
      {"status", &RunRecord::status},
      {"exit_code", &RunRecord::exit_code},
      {"message", &RunRecord::message},
      {"dofs", &RunRecord::dofs},
      {"elements", &RunRecord::elements},
      {"quadrature_points", &RunRecord::quadrature_points},
      {"steps", &RunRecord::steps},
      {"newton_iterations", &RunRecord::newton_iterations},
      {"linear_iterations", &RunRecord::linear_iterations},
      {"setup_s", &PhaseTimings::setup},
      {"quadrature_s", &PhaseTimings::quadrature},
      {"assembly_s", &PhaseTimings::assembly},
      {"analysis_s", &PhaseTimings::analysis},
      {"factorisation_s", &PhaseTimings::factorisation},
      {"solve_s", &PhaseTimings::solve},
      {"total_s", &PhaseTimings::total},
      {"events", &RunRecord::events},
      {"refinements", &RunRecord::refinements},
      {"event_geometry_s", &RunRecord::event_geometry_seconds},
      {"event_integration_s", &RunRecord::event_integration_seconds},
      {"event_pattern_s", &RunRecord::event_pattern_seconds},
      {"event_transfer_s", &RunRecord::event_transfer_seconds},
      {"wall_s", &RunRecord::wall_seconds},
      {"peak_memory_mib", &RunRecord::peak_memory_mib},
      {"rms_error", &RunRecord::rms_error},
      {"max_error", &RunRecord::max_error},
      {"relative_rms_error", &RunRecord::relative_rms_error},
      {"report_error", &RunRecord::report_error},
      {"field_l2_error", &RunRecord::field_l2_error},
      {"field_h1_error", &RunRecord::field_h1_error},
      {"scene", &RunRecord::scene},
      {"date", &RunRecord::date},
      {"cpu", &RunRecord::cpu},
      {"cores", &RunRecord::cores},
      {"threads", &RunRecord::threads},
      {"blas", &RunRecord::blas}};
  return table;
}

template <class... Functions>
struct Overloaded : Functions... {
  using Functions::operator()...;
};

std::string field_text(const RunRecord& record, const Member& member) {
  return std::visit(Overloaded{[&](std::string RunRecord::*m) { return record.*m; },
                               [&](bool RunRecord::*m) { return std::string(record.*m ? "1" : "0"); },
                               [&](int RunRecord::*m) { return std::to_string(record.*m); },
                               [&](long long RunRecord::*m) { return std::to_string(record.*m); },
                               [&](double RunRecord::*m) { return number_text(record.*m); },
                               [&](double PhaseTimings::*m) { return number_text(record.timings.*m); }},
                    member);
}

// An empty number field is NaN (an unknown error); anything else must parse whole.
double parse_number(const std::string& field, const std::string& where, const std::string& column) {
  if (field.empty()) return std::numeric_limits<double>::quiet_NaN();
  double value = 0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (error != std::errc() || end != field.data() + field.size())
    throw InputError(input_message(where, column, "expected a number, got '" + field + "'"));
  return value;
}

void set_field(RunRecord& record, const Member& member, const std::string& field, const std::string& where,
               const std::string& column) {
  const auto number = [&] { return parse_number(field, where, column); };
  std::visit(Overloaded{[&](std::string RunRecord::*m) { record.*m = field; },
                        [&](bool RunRecord::*m) { record.*m = field == "1"; },
                        [&](int RunRecord::*m) { record.*m = static_cast<int>(number()); },
                        [&](long long RunRecord::*m) { record.*m = static_cast<long long>(number()); },
                        [&](double RunRecord::*m) { record.*m = number(); },
                        [&](double PhaseTimings::*m) { record.timings.*m = number(); }},
             member);
}

// The fields of one CSV record starting at `at`; advances `at` past its line end.
std::vector<std::string> parse_record(const std::string& text, std::size_t& at) {
  std::vector<std::string> fields(1);
  bool quoted_field = false;
  for (; at < text.size(); ++at) {
    const char c = text[at];
    if (quoted_field) {
      if (c == '"' && at + 1 < text.size() && text[at + 1] == '"') fields.back() += text[++at];
      else if (c == '"') quoted_field = false;
      else fields.back() += c;
    } else if (c == '"') {
      quoted_field = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c == '\n') {
      ++at;
      break;
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  return fields;
}

}  // namespace

void write_results_csv(const std::filesystem::path& file, const std::vector<RunRecord>& records) {
  std::string text;
  for (const auto& [name, member] : columns()) {
    if (!text.empty()) text += ',';
    text += name;
  }
  text += '\n';
  for (const RunRecord& record : records) {
    for (std::size_t k = 0; k < columns().size(); ++k) {
      if (k > 0) text += ',';
      text += quoted(field_text(record, columns()[k].second));
    }
    text += '\n';
  }
  write_file_atomically(file, text);
}

std::vector<RunRecord> read_results_csv(const std::filesystem::path& file) {
  std::ifstream stream(file, std::ios::binary);
  if (!stream) throw InputError(input_message(file.string(), "", "expected a readable results.csv"));
  std::ostringstream content;
  content << stream.rdbuf();
  const std::string text = content.str();
  std::size_t at = 0;
  const std::vector<std::string> header = parse_record(text, at);
  std::vector<RunRecord> records;
  for (int line = 2; at < text.size(); ++line) {
    const std::vector<std::string> fields = parse_record(text, at);
    const std::string where = file.string() + ": line " + std::to_string(line);
    if (fields.size() != header.size())
      throw InputError(input_message(
          where, "", "expected " + std::to_string(header.size()) + " fields, got " + std::to_string(fields.size())));
    RunRecord record;
    for (const auto& [name, member] : columns()) {
      const auto found = std::find(header.begin(), header.end(), name);
      // These came later: a cached record.csv from before them has none (NaN).
      const bool later = name == "report_error" || name == "field_l2_error" || name == "field_h1_error" ||
                         name == "relative_rms_error" || name == "events" || name.starts_with("event_") ||
                         name == "refinements";
      if (found == header.end() && later) continue;
      if (found == header.end()) throw InputError(input_message(where, "", "missing column '" + name + "'"));
      set_field(record, member, fields[found - header.begin()], where, name);
    }
    records.push_back(std::move(record));
  }
  return records;
}

}  // namespace altfem
