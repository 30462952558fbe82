# Precompiled headers (issue #38, the clean build on 2 cores). Most translation units
# spent more than half their compile time parsing Eigen, the standard library,
# GoogleTest and nlohmann-json; each target instead reuses (REUSE_FROM) a precompiled
# header built once by an object library of its own kind, from an empty source:
#  - GCC uses a precompiled header only where the macros its headers test are the same:
#    -fopenmp defines _OPENMP and _REENTRANT, GoogleTest's users GTEST_HAS_PTHREAD;
#  - nlohmann-json costs ~3 s to parse but ~1 s to load precompiled (Eigen: 3.4 s and
#    0.3 s), so only the targets that link it get it in theirs.
# docs/performance.md, "Build time", has the figures. -DALTFEM_PCH=OFF builds without
# them (and so checks that each file includes what it uses).

# What most translation units include (counted from the build's dependency files).
set(altfem_pch_headers
  <algorithm> <array> <cmath> <cstdio> <filesystem> <fstream> <functional> <iostream> <limits>
  <map> <memory> <numeric> <optional> <random> <set> <span> <sstream> <stdexcept> <string>
  <string_view> <unordered_map> <variant> <vector>
  <Eigen/Core> <Eigen/Geometry> <Eigen/LU> <Eigen/Cholesky> <Eigen/QR> <Eigen/Eigenvalues> <Eigen/SVD>
  <Eigen/Sparse>)

# The libraries whose compile flags `target` gets: those it links and, recursively,
# those they pass on (a static library's private dependency is linked, not passed on).
function(altfem_flag_sources target result)
  get_property(pending TARGET ${target} PROPERTY LINK_LIBRARIES)
  set(seen)
  while(NOT pending STREQUAL "")
    list(POP_FRONT pending item)
    if(item IN_LIST seen OR item MATCHES "^\\$<LINK_ONLY:")
      continue()
    endif()
    list(APPEND seen ${item})
    if(TARGET ${item})
      get_property(passed_on TARGET ${item} PROPERTY INTERFACE_LINK_LIBRARIES)
      list(APPEND pending ${passed_on})
    endif()
  endwhile()
  set(${result} ${seen} PARENT_SCOPE)
endfunction()

# Every C++ target under `directory` reuses the precompiled header of its kind,
# altfem_pch[_tests][_openmp][_json], made the first time a target needs it.
function(altfem_use_precompiled_headers directory)
  get_property(targets DIRECTORY ${directory} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(NOT type MATCHES "^(EXECUTABLE|STATIC_LIBRARY|SHARED_LIBRARY|OBJECT_LIBRARY)$"
       OR target MATCHES "^altfem_pch(_|$)")
      continue()
    endif()
    altfem_flag_sources(${target} libraries)
    set(donor altfem_pch)
    set(donor_libraries Eigen3::Eigen)
    set(headers ${altfem_pch_headers})
    if("GTest::gtest" IN_LIST libraries)
      string(APPEND donor _tests)
      list(APPEND donor_libraries GTest::gtest)
      list(APPEND headers <gtest/gtest.h>)
    endif()
    if("OpenMP::OpenMP_CXX" IN_LIST libraries)
      string(APPEND donor _openmp)
      list(APPEND donor_libraries OpenMP::OpenMP_CXX)
    endif()
    if("nlohmann_json::nlohmann_json" IN_LIST libraries)
      string(APPEND donor _json)
      list(APPEND donor_libraries nlohmann_json::nlohmann_json)
      list(APPEND headers <nlohmann/json.hpp>)
    endif()
    if(NOT TARGET ${donor})
      add_library(${donor} OBJECT ${CMAKE_BINARY_DIR}/altfem_pch_donor.cpp)
      target_link_libraries(${donor} PRIVATE ${donor_libraries})
      target_precompile_headers(${donor} PRIVATE ${headers})
    endif()
    target_precompile_headers(${target} REUSE_FROM ${donor})
  endforeach()
  get_property(subdirectories DIRECTORY ${directory} PROPERTY SUBDIRECTORIES)
  foreach(subdirectory IN LISTS subdirectories)
    altfem_use_precompiled_headers(${subdirectory})
  endforeach()
endfunction()

file(CONFIGURE OUTPUT ${CMAKE_BINARY_DIR}/altfem_pch_donor.cpp CONTENT "")
altfem_use_precompiled_headers(${PROJECT_SOURCE_DIR})
