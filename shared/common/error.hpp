#pragma once
// The two kinds of failure altfem reports to its users, and their exit codes
// (docs/conventions.md, "Command line and outputs"): bad input exits 2, a numerical
// failure exits 3; anything else that escapes is an internal error (exit 1).
#include <stdexcept>
#include <string>

namespace altfem {

enum ExitCode : int { exit_ok = 0, exit_internal = 1, exit_bad_input = 2, exit_numerical = 3 };

/// Bad input: a file, a scene key or a command-line argument. The message is one
/// line that names the file and the line or JSON pointer, and what was expected,
/// e.g. "scene.json: /material/poisson_ratio: must be < 0.5, got 0.5".
class InputError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// A numerical failure: Newton not converging, a singular matrix, an inverted
/// element. The message says where (step, iteration, element).
class NumericalError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// "file: where: what" — the one-line form of every input error.
std::string input_message(const std::string& file, const std::string& where, const std::string& what);

}  // namespace altfem
