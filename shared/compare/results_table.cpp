#include "shared/compare/results_table.hpp"

#include <charconv>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "shared/common/error.hpp"
#include "shared/io/atomic_file.hpp"

namespace altfem {

namespace {

using Row = std::map<std::string, std::string>;

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

Row row_of(const RunRecord& r) {
  const PhaseTimings& t = r.timings;
  return {{"hash", r.hash}, {"method", r.method}, {"element", r.element}, {"label", r.label},
          {"overrides", r.overrides}, {"is_reference", r.is_reference ? "1" : "0"}, {"status", r.status},
          {"exit_code", std::to_string(r.exit_code)}, {"message", r.message}, {"dofs", std::to_string(r.dofs)},
          {"elements", std::to_string(r.elements)}, {"quadrature_points", std::to_string(r.quadrature_points)},
          {"steps", std::to_string(r.steps)}, {"newton_iterations", std::to_string(r.newton_iterations)},
          {"linear_iterations", std::to_string(r.linear_iterations)}, {"setup_s", number_text(t.setup)},
          {"quadrature_s", number_text(t.quadrature)}, {"assembly_s", number_text(t.assembly)},
          {"analysis_s", number_text(t.analysis)}, {"factorisation_s", number_text(t.factorisation)},
          {"solve_s", number_text(t.solve)}, {"total_s", number_text(t.total)},
          {"wall_s", number_text(r.wall_seconds)}, {"peak_memory_mib", number_text(r.peak_memory_mib)},
          {"rms_error", number_text(r.rms_error)}, {"max_error", number_text(r.max_error)}, {"scene", r.scene},
          {"date", r.date}, {"cpu", r.cpu}, {"cores", std::to_string(r.cores)},
          {"threads", std::to_string(r.threads)}, {"blas", r.blas}};
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

class RowReader {
public:
  RowReader(const Row& row, std::string where) : row_(row), where_(std::move(where)) {}
  const std::string& text(const std::string& column) const {
    const auto found = row_.find(column);
    if (found == row_.end()) throw InputError(input_message(where_, "", "missing column '" + column + "'"));
    return found->second;
  }
  double number(const std::string& column) const {
    const std::string& field = text(column);
    if (field.empty()) return std::numeric_limits<double>::quiet_NaN();
    double value = 0;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (error != std::errc() || end != field.data() + field.size())
      throw InputError(input_message(where_, column, "expected a number, got '" + field + "'"));
    return value;
  }
  long long integer(const std::string& column) const { return static_cast<long long>(number(column)); }

private:
  const Row& row_;
  std::string where_;
};

}  // namespace

const std::vector<std::string>& result_columns() {
  static const std::vector<std::string> columns{
      "hash", "method", "element", "label", "overrides", "is_reference", "status", "exit_code", "message", "dofs",
      "elements", "quadrature_points", "steps", "newton_iterations", "linear_iterations", "setup_s", "quadrature_s",
      "assembly_s", "analysis_s", "factorisation_s", "solve_s", "total_s", "wall_s", "peak_memory_mib", "rms_error",
      "max_error", "scene", "date", "cpu", "cores", "threads", "blas"};
  return columns;
}

void write_results_csv(const std::filesystem::path& file, const std::vector<RunRecord>& records) {
  std::string text;
  for (const auto& column : result_columns()) text += (text.empty() ? "" : ",") + column;
  text += '\n';
  for (const RunRecord& record : records) {
    const Row row = row_of(record);
    std::string line;
    for (const auto& column : result_columns()) line += (line.empty() ? "" : ",") + quoted(row.at(column));
    text += line + '\n';
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
      throw InputError(input_message(where, "", "expected " + std::to_string(header.size()) + " fields, got " +
                                                    std::to_string(fields.size())));
    Row row;
    for (std::size_t i = 0; i < header.size(); ++i) row[header[i]] = fields[i];
    const RowReader r(row, where);
    RunRecord record;
    record.hash = r.text("hash");
    record.method = r.text("method");
    record.element = r.text("element");
    record.label = r.text("label");
    record.overrides = r.text("overrides");
    record.is_reference = r.text("is_reference") == "1";
    record.status = r.text("status");
    record.exit_code = static_cast<int>(r.integer("exit_code"));
    record.message = r.text("message");
    record.dofs = r.integer("dofs");
    record.elements = r.integer("elements");
    record.quadrature_points = r.integer("quadrature_points");
    record.steps = r.integer("steps");
    record.newton_iterations = r.integer("newton_iterations");
    record.linear_iterations = r.integer("linear_iterations");
    record.timings = {r.number("setup_s"), r.number("quadrature_s"), r.number("assembly_s"), r.number("analysis_s"),
                      r.number("factorisation_s"), r.number("solve_s"), r.number("total_s")};
    record.wall_seconds = r.number("wall_s");
    record.peak_memory_mib = r.number("peak_memory_mib");
    record.rms_error = r.number("rms_error");
    record.max_error = r.number("max_error");
    record.scene = r.text("scene");
    record.date = r.text("date");
    record.cpu = r.text("cpu");
    record.cores = static_cast<int>(r.integer("cores"));
    record.threads = static_cast<int>(r.integer("threads"));
    record.blas = r.text("blas");
    records.push_back(std::move(record));
  }
  return records;
}

}  // namespace altfem
