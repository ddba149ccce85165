# The commit `clrender --version` reports (docs/command-line.md, Version): a source file
# regenerated at every build by cmake/write_version.cmake, so that a new commit or an edited
# tree shows without configuring again. Defines BUILD_COMMIT_CPP for clrender_core.

set(BUILD_COMMIT_CPP "${CMAKE_BINARY_DIR}/generated/build_commit.cpp")
add_custom_target(clrender_version_info
    COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${CMAKE_SOURCE_DIR} -DOUTPUT=${BUILD_COMMIT_CPP}
            -P ${CMAKE_SOURCE_DIR}/cmake/write_version.cmake
    BYPRODUCTS "${BUILD_COMMIT_CPP}"
    COMMENT "Reading the git commit for --version"
    VERBATIM)
