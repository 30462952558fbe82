#include "shared/io/json_file.hpp"

#include <cmath>

#include "shared/common/error.hpp"
#include "shared/io/atomic_file.hpp"

namespace altfem {

namespace {

void check_finite(const std::filesystem::path& path, const nlohmann::json& value,
                  const nlohmann::json::json_pointer& where) {
  if (value.is_number_float()) {
    const double number = value.get<double>();
    if (!std::isfinite(number))
      throw NumericalError(path.string() + ": " + where.to_string() + ": expected a finite number, got " +
                           std::to_string(number));
  } else if (value.is_object()) {
    for (const auto& [key, item] : value.items()) check_finite(path, item, where / key);
  } else if (value.is_array()) {
    for (std::size_t index = 0; index < value.size(); ++index) check_finite(path, value[index], where / index);
  }
}

}  // namespace

void write_json_file(const std::filesystem::path& path, const nlohmann::json& value) {
  check_finite(path, value, nlohmann::json::json_pointer());
  write_file_atomically(path, value.dump(2) + "\n");
}

}  // namespace altfem
