#include "shared/solve/process_ranks.hpp"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

#include "shared/common/error.hpp"

#ifdef ALTFEM_HAVE_PETSC
#include <mpi.h>
#endif

namespace altfem::ranks {
namespace {

// The number of processes mpirun started, from its environment (Open MPI's, or the
// PMI variable other launchers set); 0 when no launcher started this one.
int launched_processes() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* value = std::getenv(variable)) return std::max(1, std::atoi(value));
  return 0;
}

bool& matrix_shares() {
  static bool share = false;
  return share;
}

}  // namespace

void share_matrices(bool share) { matrix_shares() = share; }
bool shares_matrices() { return distributed() && matrix_shares(); }

#ifdef ALTFEM_HAVE_PETSC

namespace {

struct World {
  int index = 0;
  int count = 1;
};

World& world() {
  static World instance;
  return instance;
}

// Stops MPI at exit, after PETSc: PETSc starts later (with the first PETSc solver), so
// its session, a static object too, is destroyed first.
struct MpiSession {
  MpiSession() {
    int provided = 0;
    // OpenMP threads assemble, but only the main thread calls MPI.
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &world().index);
    MPI_Comm_size(MPI_COMM_WORLD, &world().count);
  }
  ~MpiSession() {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized) MPI_Finalize();
  }
};

}  // namespace

void start() {
  if (launched_processes() > 0) static MpiSession session;
}

std::string library() {
  // Callable before MPI starts; its first line names the implementation and version.
  char text[MPI_MAX_LIBRARY_VERSION_STRING];
  int length = 0;
  MPI_Get_library_version(text, &length);
  const std::string version(text, static_cast<size_t>(length));
  return version.substr(0, version.find_first_of(",\n"));
}

int index() { return world().index; }
int count() { return world().count; }

Alone::Alone() : index_(world().index), count_(world().count) {
  world().index = 0;
  world().count = 1;
}

Alone::~Alone() {
  world().index = index_;
  world().count = count_;
}

void sum(std::span<double> values) {
  if (!distributed()) return;
  // MPI counts in int: a Hessian's values may be more.
  constexpr size_t chunk = size_t{1} << 30;
  for (size_t start = 0; start < values.size(); start += chunk)
    MPI_Allreduce(MPI_IN_PLACE, values.data() + start, static_cast<int>(std::min(chunk, values.size() - start)),
                  MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
}

double sum(double value) {
  sum(std::span<double>(&value, 1));
  return value;
}

std::vector<double> gather(double value) {
  std::vector<double> values(static_cast<size_t>(count()), value);
  if (distributed()) MPI_Allgather(&value, 1, MPI_DOUBLE, values.data(), 1, MPI_DOUBLE, MPI_COMM_WORLD);
  return values;
}

std::vector<std::string> gather(const std::string& bytes) {
  if (!distributed()) return {bytes};
  const std::vector<double> sizes = gather(static_cast<double>(bytes.size()));
  std::vector<int> counts(sizes.size()), offsets(sizes.size(), 0);
  double total = 0;
  for (size_t rank = 0; rank < sizes.size(); ++rank) {
    // MPI counts and displacements are int.
    if (total + sizes[rank] > std::numeric_limits<int>::max()) throw std::length_error("ranks::gather: over 2 GiB");
    offsets[rank] = static_cast<int>(total);
    counts[rank] = static_cast<int>(sizes[rank]);
    total += sizes[rank];
  }
  std::string all(static_cast<size_t>(total), '\0');
  MPI_Allgatherv(bytes.data(), static_cast<int>(bytes.size()), MPI_CHAR, all.data(), counts.data(), offsets.data(),
                 MPI_CHAR, MPI_COMM_WORLD);
  std::vector<std::string> result;
  for (size_t rank = 0; rank < sizes.size(); ++rank) result.push_back(all.substr(offsets[rank], counts[rank]));
  return result;
}

void broadcast(std::span<int> values) {
  if (distributed()) MPI_Bcast(values.data(), static_cast<int>(values.size()), MPI_INT, 0, MPI_COMM_WORLD);
}

void collectively_over_ranks(const std::function<void()>& body) {
  int kind = 0;  // the exit code the failure stands for: 2 input, 3 numerical, 1 other
  std::string message;
  try {
    body();
  } catch (const InputError& error) {
    kind = exit_bad_input;
    message = error.what();
  } catch (const NumericalError& error) {
    kind = exit_numerical;
    message = error.what();
  } catch (const std::exception& error) {
    kind = exit_internal;
    message = error.what();
  }
  const int mine = kind != 0 ? index() : count();
  int first = count();
  MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  if (first == count()) return;
  int length = static_cast<int>(message.size());
  MPI_Bcast(&kind, 1, MPI_INT, first, MPI_COMM_WORLD);
  MPI_Bcast(&length, 1, MPI_INT, first, MPI_COMM_WORLD);
  message.resize(static_cast<size_t>(length));
  MPI_Bcast(message.data(), length, MPI_CHAR, first, MPI_COMM_WORLD);
  if (kind == exit_bad_input) throw InputError(message);
  if (kind == exit_numerical) throw NumericalError("rank " + std::to_string(first) + ": " + message);
  throw std::runtime_error("rank " + std::to_string(first) + ": " + message);
}

#else

void start() {
  if (const int processes = launched_processes(); processes > 1)
    throw InputError("mpirun started " + std::to_string(processes) +
                     " processes, but this build has no MPI (it comes with PETSc: CMake -DALTFEM_PETSC=ON)");
}

std::string library() { return {}; }
int index() { return 0; }
int count() { return 1; }
Alone::Alone() : index_(0), count_(1) {}
Alone::~Alone() = default;
void sum(std::span<double>) {}
double sum(double value) { return value; }
std::vector<double> gather(double value) { return {value}; }
std::vector<std::string> gather(const std::string& bytes) { return {bytes}; }
void broadcast(std::span<int>) {}
void collectively_over_ranks(const std::function<void()>& body) { body(); }

#endif

}  // namespace altfem::ranks
