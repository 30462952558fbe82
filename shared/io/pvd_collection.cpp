#include "shared/io/pvd_collection.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include "shared/common/error.hpp"
#include "shared/io/atomic_file.hpp"
#include "shared/io/xml_attribute.hpp"

namespace altfem {

namespace {

/// The shortest text that reads back to the same double.
std::string round_trip_text(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace

PvdCollection::PvdCollection(std::filesystem::path pvd_path) : pvd_path_(std::move(pvd_path)) {}

void PvdCollection::add(double time, const std::filesystem::path& vtu_file, int part) {
  if (!std::isfinite(time))
    throw NumericalError(pvd_path_.string() + ": frame " + vtu_file.string() + ": expected a finite time, got " +
                         std::to_string(time));
  std::filesystem::path file = vtu_file;
  if (file.is_absolute()) file = file.lexically_relative(std::filesystem::absolute(pvd_path_).parent_path());
  entries_.push_back({time, file, part});
}

void PvdCollection::write() const {
  std::string text =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const Entry& entry : entries_)
    text += "    <DataSet timestep=\"" + round_trip_text(entry.time) + "\" group=\"\" part=\"" +
            std::to_string(entry.part) + "\" file=\"" + xml_attribute(entry.file.generic_string()) + "\"/>\n";
  text += "  </Collection>\n</VTKFile>\n";
  write_file_atomically(pvd_path_, text);
}

}  // namespace altfem
