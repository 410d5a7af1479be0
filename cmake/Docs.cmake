# The API reference (docs/Doxyfile.in): target `docs` when Doxygen (Debian `doxygen`) is
# installed. The run fails on any Doxygen warning; tests/CMakeLists.txt runs it as a test.
find_package(Doxygen QUIET)
if(DOXYGEN_FOUND)
  set(DOCS_OUTPUT_DIR ${PROJECT_BINARY_DIR}/docs)
  configure_file(${PROJECT_SOURCE_DIR}/docs/Doxyfile.in ${DOCS_OUTPUT_DIR}/Doxyfile @ONLY)
  add_custom_target(docs
    COMMAND Doxygen::doxygen ${DOCS_OUTPUT_DIR}/Doxyfile
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    COMMENT "API reference (Doxygen) in ${DOCS_OUTPUT_DIR}/html"
    VERBATIM)
else()
  message(STATUS "doxygen not found: no docs target (Debian package doxygen)")
endif()
