# globe_version: the header globe_version.hpp holds the project version, and one generated source
# the checkout's revision at configure time (for --version).
find_package(Git QUIET)
set(GLOBE_SOURCE_REVISION "unknown")
if(GIT_FOUND AND EXISTS ${PROJECT_SOURCE_DIR}/.git)
  execute_process(
    COMMAND ${GIT_EXECUTABLE} describe --always --dirty --abbrev=10
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    OUTPUT_VARIABLE GLOBE_SOURCE_REVISION
    OUTPUT_STRIP_TRAILING_WHITESPACE
    ERROR_QUIET)
  if(NOT GLOBE_SOURCE_REVISION)
    set(GLOBE_SOURCE_REVISION "unknown")
  endif()
endif()
configure_file(${PROJECT_SOURCE_DIR}/cmake/globe_version.hpp.in
               ${PROJECT_BINARY_DIR}/generated/globe_version.hpp @ONLY)
configure_file(${PROJECT_SOURCE_DIR}/cmake/globe_revision.cpp.in
               ${PROJECT_BINARY_DIR}/generated/globe_revision.cpp @ONLY)
add_library(globe_version STATIC ${PROJECT_BINARY_DIR}/generated/globe_revision.cpp)
target_include_directories(globe_version PUBLIC ${PROJECT_BINARY_DIR}/generated)
