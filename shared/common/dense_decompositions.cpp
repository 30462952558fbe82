// The one copy of the decompositions dense_decompositions.hpp declares.
#define ALTFEM_DEFINE_DENSE_DECOMPOSITIONS
#include "shared/common/dense_decompositions.hpp"
