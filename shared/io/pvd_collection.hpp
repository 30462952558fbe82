#pragma once
// ParaView data (.pvd) collections: the time series of VTU frames of one run.
#include <filesystem>
#include <vector>

namespace altfem {

/// The list of (time, part, file) entries of a .pvd file, written on demand, so a
/// run can rewrite it after every frame and an interrupted run still leaves a
/// readable collection of the frames written so far.
class PvdCollection {
public:
  explicit PvdCollection(std::filesystem::path pvd_path);

  /// Adds a frame. `vtu_file` is relative to the folder of the .pvd (an absolute
  /// path is made relative to it); `part` tells apart several grids of one time
  /// step (e.g. background mesh and embedded surface). Throws NumericalError for a
  /// non-finite time.
  void add(double time, const std::filesystem::path& vtu_file, int part = 0);
  /// Writes the .pvd atomically (write_file_atomically).
  void write() const;

  const std::filesystem::path& path() const { return pvd_path_; }

private:
  struct Entry {
    double time;
    std::filesystem::path file;
    int part;
  };
  std::filesystem::path pvd_path_;
  std::vector<Entry> entries_;
};

}  // namespace altfem
