# Script mode (cmake -P), run after each test program links: lists its GoogleTest tests and writes
# the CTest file that registers them, one CTest test per gtest suite ("PREFIX.Suite.*", run as
# --gtest_filter=Suite.*), and one for each test named in SOLO ("PREFIX.Suite.Test"), which then
# leaves its suite's group. Why groups: a test process costs 90 ms before main() (GDAL's and
# OSMesa's libraries loading), which one process per test paid a thousand times
# (docs/performance/ci-time.md). Each group writes GoogleTest's XML report into XML_DIR, from
# which tools/run-tests.sh counts and names every test that ran, failed or was skipped.
#
# Variables: TEST_EXECUTABLE, TEST_PREFIX, WORKING_DIR, CTEST_FILE, XML_DIR, SOLO (list of
# Suite.Test) and PROPERTIES (for set_tests_properties): lists with '|' for ';'.
cmake_minimum_required(VERSION 3.20)

execute_process(COMMAND "${TEST_EXECUTABLE}" --gtest_list_tests
  WORKING_DIRECTORY "${WORKING_DIR}" TIMEOUT 60
  OUTPUT_VARIABLE listing RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${TEST_EXECUTABLE} --gtest_list_tests failed (${result}):\n${listing}")
endif()

# Lines: "Suite." (or "Prefix/Suite.  # TypeParam = ...") then "  Test" (or "  Test/0  # GetParam() = ...").
string(REPLACE ";" "" listing "${listing}")  # parameter values may hold ';'; names cannot
string(REPLACE "\n" ";" lines "${listing}")
set(suites "")
foreach(line IN LISTS lines)
  if(line MATCHES "^Running main|^$")
    continue()
  elseif(line MATCHES "^([^ #]+)\\.")
    set(suite "${CMAKE_MATCH_1}")
    list(APPEND suites "${suite}")
    set(tests_${suite} "")
  elseif(line MATCHES "^  ([^ #]+)")
    list(APPEND tests_${suite} "${CMAKE_MATCH_1}")
  endif()
endforeach()

string(REPLACE "|" ";" properties "${PROPERTIES}")
string(REPLACE "|" ";" SOLO "${SOLO}")
set(script "")
set(registered 0)
# add_test + properties for one CTest test running FILTER, its report in XML_DIR/NAME.xml.
macro(register name filter)
  string(REGEX REPLACE "\\.\\*$" "" report "${name}")  # PREFIX.Suite.* reports as PREFIX.Suite.xml
  string(REGEX REPLACE "[^A-Za-z0-9_.-]" "_" report "${report}")
  string(APPEND script "add_test([==[${name}]==] [==[${TEST_EXECUTABLE}]==] "
    "[==[--gtest_filter=${filter}]==] [==[--gtest_output=xml:${XML_DIR}/${report}.xml]==])\n"
    "set_tests_properties([==[${name}]==] PROPERTIES WORKING_DIRECTORY [==[${WORKING_DIR}]==]")
  foreach(p IN LISTS properties)
    string(APPEND script " [==[${p}]==]")
  endforeach()
  string(APPEND script ")\n")
  math(EXPR registered "${registered} + 1")
endmacro()

set(unused_solo ${SOLO})
foreach(suite IN LISTS suites)
  set(excluded "")
  foreach(test IN LISTS tests_${suite})
    if("${suite}.${test}" IN_LIST SOLO)
      register("${TEST_PREFIX}${suite}.${test}" "${suite}.${test}")
      string(APPEND excluded ":${suite}.${test}")
      list(REMOVE_ITEM unused_solo "${suite}.${test}")
    endif()
  endforeach()
  list(LENGTH tests_${suite} count)
  string(REGEX MATCHALL ":" solo_marks "${excluded}")
  list(LENGTH solo_marks solo_count)
  if(count GREATER solo_count)
    if(excluded)
      string(SUBSTRING "${excluded}" 1 -1 excluded)
      set(excluded "-${excluded}")
    endif()
    register("${TEST_PREFIX}${suite}.*" "${suite}.*${excluded}")
  endif()
endforeach()
if(unused_solo)
  message(FATAL_ERROR "${TEST_EXECUTABLE} has no test ${unused_solo} (SOLO in its globe_test())")
endif()
if(registered EQUAL 0)
  message(FATAL_ERROR "${TEST_EXECUTABLE} lists no tests")
endif()
file(WRITE "${CTEST_FILE}.tmp" "${script}")
file(RENAME "${CTEST_FILE}.tmp" "${CTEST_FILE}")
