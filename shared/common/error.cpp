#include "shared/common/error.hpp"

namespace altfem {

std::string input_message(const std::string& file, const std::string& where, const std::string& what) {
  std::string message = file;
  if (!where.empty()) message += ": " + where;
  message += ": " + what;
  return message;
}

}  // namespace altfem
