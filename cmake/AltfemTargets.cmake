# altfem_library(NAME folder DEPENDS ...): one static library per shared/ folder,
# from the folder's *.cpp. Files named *.cgal.cpp are the only ones that see CGAL
# (slow to compile, and it adds -frounding-math that the numerical kernels must
# not get): they form a private object library of their own.
function(altfem_library name)
  cmake_parse_arguments(ARG "" "" "DEPENDS;PRIVATE_DEPENDS" ${ARGN})
  file(GLOB all_sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  file(GLOB cgal_sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cgal.cpp)
  set(plain_sources ${all_sources})
  if(cgal_sources)
    list(REMOVE_ITEM plain_sources ${cgal_sources})
  endif()
  if(NOT all_sources)
    # A header-only folder.
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE ${PROJECT_SOURCE_DIR})
    target_link_libraries(${name} INTERFACE ${ARG_DEPENDS} Eigen3::Eigen)
    return()
  endif()
  add_library(${name} STATIC ${plain_sources})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PUBLIC ${ARG_DEPENDS} Eigen3::Eigen PRIVATE ${ARG_PRIVATE_DEPENDS})
  if(cgal_sources)
    add_library(${name}_cgal OBJECT ${cgal_sources})
    target_include_directories(${name}_cgal PRIVATE ${PROJECT_SOURCE_DIR})
    target_link_libraries(${name}_cgal PRIVATE CGAL::CGAL ${ARG_DEPENDS} Eigen3::Eigen)
    target_sources(${name} PRIVATE $<TARGET_OBJECTS:${name}_cgal>)
    target_link_libraries(${name} PRIVATE CGAL::CGAL)
  endif()
endfunction()

# altfem_test(NAME LABEL label SOURCES ... DEPENDS ... [TEST_FILTER f]): one GoogleTest
# executable, registered with ctest under the label (unit, verify or cli); TEST_FILTER
# is gtest_discover_tests' (tests/CMakeLists.txt: the *FullSize suites ctest leaves out).
function(altfem_test name)
  cmake_parse_arguments(ARG "" "LABEL;TIMEOUT;TEST_FILTER" "SOURCES;DEPENDS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPENDS} GTest::gtest_main)
  target_compile_definitions(${name} PRIVATE
    ALTFEM_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    ALTFEM_BINARY_DIR="${PROJECT_BINARY_DIR}")
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 600)
  endif()
  set(filter)
  if(ARG_TEST_FILTER)
    set(filter TEST_FILTER "${ARG_TEST_FILTER}")
  endif()
  gtest_discover_tests(${name} ${filter} PROPERTIES LABELS ${ARG_LABEL} TIMEOUT ${ARG_TIMEOUT}
                       DISCOVERY_TIMEOUT 60)
endfunction()
