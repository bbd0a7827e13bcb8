# Compiler warnings and sanitizers, applied to every globe target through globe_warnings.
add_library(globe_warnings INTERFACE)
target_compile_options(globe_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
  -Wno-sign-conversion)
if(GLOBE_WERROR)
  target_compile_options(globe_warnings INTERFACE -Werror)
endif()
# ASan+UBSan instrument the project's libraries and programs (src/ and apps/ call
# globe_instrument()), at -O1 with line tables (the sanitizers' advice; all a report's stack
# trace needs). The tests' own code is compiled exactly as in the plain build, so a sanitizer
# build takes those objects from the compiler cache (docs/performance/ci-time.md); every byte a
# test feeds goes through instrumented readers all the same.
set(GLOBE_INSTRUMENT_OPTIONS "")
if(GLOBE_SANITIZE)
  set(GLOBE_INSTRUMENT_OPTIONS -fsanitize=address,undefined -fno-omit-frame-pointer
    -fno-sanitize-recover=undefined -O1 -g1)
  add_link_options(-fsanitize=address,undefined)
endif()
macro(globe_instrument)
  add_compile_options(${GLOBE_INSTRUMENT_OPTIONS})
endmacro()
option(GLOBE_SANITIZE_THREAD "Build with ThreadSanitizer (CI: tools/sanitizers/tsan-tests.txt)" OFF)
if(GLOBE_SANITIZE_THREAD)
  if(GLOBE_SANITIZE)
    message(FATAL_ERROR "GLOBE_SANITIZE and GLOBE_SANITIZE_THREAD cannot be combined")
  endif()
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  add_link_options(-fsanitize=thread)
endif()
# libFuzzer targets in tests/fuzz (clang only): everything is instrumented for coverage and
# built with ASan+UBSan; only the fuzz_* executables link the fuzzer's main.
option(GLOBE_FUZZ "Build the libFuzzer targets (needs clang)" OFF)
if(GLOBE_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "GLOBE_FUZZ=ON needs clang: -DCMAKE_CXX_COMPILER=clang++")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
    -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()

# Precompiled headers (tools/bench/build_time.sh measures what they save: docs/performance/build-time.md):
# the standard and GLM headers nearly every file includes, and GoogleTest for the tests.
option(GLOBE_PRECOMPILED_HEADERS "Precompile the common standard, GLM and GoogleTest headers" OFF)
function(globe_precompile name)
  if(GLOBE_PRECOMPILED_HEADERS)
    target_precompile_headers(${name} PRIVATE <algorithm> <cmath> <cstdint> <memory> <optional>
      <string> <vector> <glm/glm.hpp> ${ARGN})
  endif()
endfunction()

# globe_module(NAME SOURCES... PUBLIC_HEADERS... DEPENDS targets...): one static library per
# src/<module>. PUBLIC_HEADERS are the library's interface, the headers other libraries and the
# programs may include; every other header in the folder is private to it (tools/docs/
# check_headers.py, a test, holds the rest of the project to that).
function(globe_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_HEADERS;DEPENDS" ${ARGN})
  foreach(header IN LISTS ARG_PUBLIC_HEADERS)
    if(NOT EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${header})
      message(FATAL_ERROR "${name}: PUBLIC_HEADERS names ${header}, which is not in ${CMAKE_CURRENT_SOURCE_DIR}")
    endif()
  endforeach()
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR}/src)
  target_link_libraries(${name} PUBLIC ${ARG_DEPENDS} PRIVATE globe_warnings)
  globe_precompile(${name})
endfunction()

# globe_test(NAME [OPTIMIZED] SOURCES... DEPENDS targets... [SOLO Suite.Test...]): a GoogleTest executable
# registered with CTest, one CTest test per suite, and one per SOLO test (a test that must have a
# process of its own: cmake/GlobeTestGroupsScript.cmake).
function(globe_test name)
  cmake_parse_arguments(ARG "OPTIMIZED" "" "SOURCES;DEPENDS;SOLO" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPENDS} GTest::gtest_main GTest::gmock globe_warnings
    globe_build_paths)  # tests/support/build_paths.hpp
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR})  # tests/support/...
  # The tests' own code unoptimised (-O0 compiles in 0.7 of -O1's time, -O1 in 0.75 of -O2's;
  # what they test, the libraries and programs, keeps the build type's optimisation), except
  # where a test's own loops are the work (OPTIMIZED: the stress tests' 10^7 points at -O1):
  # docs/performance/ci-time.md (issue 47's ninth session).
  if(CMAKE_BUILD_TYPE STREQUAL "RelWithDebInfo" OR CMAKE_BUILD_TYPE STREQUAL "Release")
    if(ARG_OPTIMIZED)
      target_compile_options(${name} PRIVATE -O1)
    else()
      target_compile_options(${name} PRIVATE -O0)
    endif()
  endif()
  if(TARGET globe_tests)  # tools/run-tests.sh builds this: the tests and what they run
    add_dependencies(globe_tests ${name})
  endif()
  globe_precompile(${name} <gtest/gtest.h>)
  # The fixtures the test processes share (tests/support/shared_fixture.hpp) live for one CTest
  # run: its setup test empties the folder first, its cleanup test removes it last.
  globe_register_test_groups(${name} "${ARG_SOLO}" TIMEOUT 600 FIXTURES_REQUIRED
    globe_shared_fixtures ENVIRONMENT GLOBE_TEST_FIXTURES=${GLOBE_TEST_FIXTURES})
endfunction()

# After NAME links, its tests are listed and registered (cmake/GlobeTestGroupsScript.cmake); the
# reports go to GLOBE_GTEST_XML_DIR. Before it has linked, CTest sees one test saying so.
set(GLOBE_GTEST_XML_DIR "${PROJECT_BINARY_DIR}/Testing/gtest")
function(globe_register_test_groups name solo)
  set(base "${CMAKE_CURRENT_BINARY_DIR}/${name}")
  string(REPLACE ";" "|" properties "${ARGN}")  # one argument each on the command line
  string(REPLACE ";" "|" solo "${solo}")
  set(script "${PROJECT_SOURCE_DIR}/cmake/GlobeTestGroupsScript.cmake")
  set_property(TARGET ${name} APPEND PROPERTY LINK_DEPENDS "${script}")  # a new script relists
  add_custom_command(TARGET ${name} POST_BUILD BYPRODUCTS "${base}_tests.cmake"
    COMMAND ${CMAKE_COMMAND} -D "TEST_EXECUTABLE=$<TARGET_FILE:${name}>" -D "TEST_PREFIX=${name}."
      -D "WORKING_DIR=${CMAKE_CURRENT_BINARY_DIR}" -D "CTEST_FILE=${base}_tests.cmake"
      -D "XML_DIR=${GLOBE_GTEST_XML_DIR}" -D "SOLO=${solo}" -D "PROPERTIES=${properties}"
      -P "${script}"
    VERBATIM)
  file(WRITE "${base}_include.cmake" "if(EXISTS [==[${base}_tests.cmake]==])\n"
    "  include([==[${base}_tests.cmake]==])\n"
    "else()\n  add_test(${name}_NOT_BUILT ${name}_NOT_BUILT)\nendif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${base}_include.cmake")
endfunction()
