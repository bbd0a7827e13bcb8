# Installation (`cmake --install BUILD --prefix P`) and the Debian package (`cpack -G DEB` in the
# build directory): the two programs, their man pages, nothing from the source tree (the shaders
# are compiled in).
include(GNUInstallDirs)
install(TARGETS globe globe-tiler RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# Man pages from --help and --version (help2man), built with everything else.
find_program(HELP2MAN_EXECUTABLE help2man)
if(HELP2MAN_EXECUTABLE)
  set(pages "")
  foreach(program IN ITEMS globe globe-tiler)
    set(page ${PROJECT_BINARY_DIR}/man/${program}.1.gz)
    if(program STREQUAL "globe")
      set(summary "virtual-globe terrain viewer with real-time camera-terrain collision")
    else()
      set(summary "build elevation pyramids and imagery layers for globe")
    endif()
    add_custom_command(
      OUTPUT ${page}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/man
      COMMAND ${HELP2MAN_EXECUTABLE} --no-info --no-discard-stderr --name=${summary}
              --output=${PROJECT_BINARY_DIR}/man/${program}.1 $<TARGET_FILE:${program}>
      COMMAND gzip -9nf ${PROJECT_BINARY_DIR}/man/${program}.1
      DEPENDS ${program}
      COMMENT "Man page ${program}.1"
      VERBATIM)
    list(APPEND pages ${page})
  endforeach()
  add_custom_target(globe_man ALL DEPENDS ${pages})
  install(FILES ${pages} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
else()
  message(STATUS "help2man not found: no man pages (tools/install-deps.sh installs it)")
endif()

set(CPACK_PACKAGE_NAME globe)
set(CPACK_PACKAGE_VENDOR "globe")
set(CPACK_PACKAGE_CONTACT "globe maintainers <globe@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Virtual-globe terrain viewer with real-time camera-terrain collision")
set(CPACK_PACKAGE_DESCRIPTION
    "Streams GTOPO30 and GDAL elevation and imagery tiled into a lat/long quadtree, renders it with OpenGL (a GLFW window or headless OSMesa) and keeps the camera out of the terrain with QOTCD.")
set(CPACK_PACKAGE_HOMEPAGE_URL "https://localhost/globe")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# Runtime dependencies from the linked libraries (dpkg-shlibdeps); the Mesa drivers a GLFW window
# needs are loaded at run time, so they are named; ffmpeg only for `globe play --video`.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libgl1-mesa-dri")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "ffmpeg")
set(CPACK_STRIP_FILES ON)
include(CPack)

# Bash completion (bash-completion loads completions/<command>; both names share one script).
install(FILES ${PROJECT_SOURCE_DIR}/tools/completion/globe.bash
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME globe)
install(FILES ${PROJECT_SOURCE_DIR}/tools/completion/globe.bash
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME globe-tiler)
