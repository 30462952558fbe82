#pragma once
// `altfem compare`: every configuration of a scene run, measured against a reference
// and reported (docs/architecture.md, "altfem compare").
#include <filesystem>
#include <string>
#include <vector>

namespace altfem::cli {

struct CompareArguments {
  std::filesystem::path scene;
  std::vector<std::string> methods;  ///< empty: the scene's compare block, else every method
  std::vector<std::string> sweeps;   ///< "KEY=V1,V2,..."; replace the scene's sweeps if any
  std::string reference;             ///< "METHOD[:KEY=VALUE,...]"; empty: the scene's, else the finest run
  int jobs = 1;
  bool force = false;
  std::filesystem::path output;
};

int compare_command(const CompareArguments& arguments);

}  // namespace altfem::cli
