#pragma once
#include <chrono>
#include <string>

namespace altfem {

/// Progress of a long run on stderr: one rewritten line with the step, the Newton
/// iterations and an ETA, shown only when stderr is a terminal (quiet in CI and
/// when redirected).
class Progress {
public:
  explicit Progress(int total_steps);
  ~Progress();
  void update(int step, int newton_iterations);

private:
  int total_;
  bool enabled_;
  bool printed_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace altfem
