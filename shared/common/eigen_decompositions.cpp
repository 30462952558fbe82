// The one copy of the decompositions eigen_decompositions.hpp declares.
#define ALTFEM_DEFINE_EIGEN_DECOMPOSITIONS
#include "shared/common/eigen_decompositions.hpp"
