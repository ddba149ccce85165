# Writes the C++ source that tells `clrender --version` which commit it was built from
# (docs/command-line.md, Version). Run at every build by the clrender_version_info target:
#
#   cmake -DSOURCE_DIR=<source tree> -DOUTPUT=<file.cpp> -P cmake/write_version.cmake
#
# The commit is `git describe --always --dirty` when SOURCE_DIR is itself the top of a git
# checkout, else "unknown": a tarball unpacked inside some other repository must not report
# that repository's commit, and a machine without git must still build. The file is only
# rewritten when its text changes, so that an unchanged commit recompiles nothing.

cmake_minimum_required(VERSION 3.21)  # this script runs alone (-P): give it the project's policies

set(commit "unknown")
find_program(GIT_PROGRAM git)
if(GIT_PROGRAM)
    execute_process(COMMAND "${GIT_PROGRAM}" rev-parse --show-toplevel
                    WORKING_DIRECTORY "${SOURCE_DIR}"
                    RESULT_VARIABLE toplevel_status OUTPUT_VARIABLE toplevel
                    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    if(toplevel_status EQUAL 0)
        file(REAL_PATH "${toplevel}" toplevel)
        file(REAL_PATH "${SOURCE_DIR}" source_dir)
        if(toplevel STREQUAL source_dir)
            execute_process(COMMAND "${GIT_PROGRAM}" describe --always --dirty
                            WORKING_DIRECTORY "${SOURCE_DIR}"
                            RESULT_VARIABLE describe_status OUTPUT_VARIABLE described
                            OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
            if(describe_status EQUAL 0 AND NOT described STREQUAL "")
                set(commit "${described}")
            endif()
        endif()
    endif()
endif()

# A tag name may hold a quote; the C++ string literal must stay one.
string(REPLACE "\\" "\\\\" commit "${commit}")
string(REPLACE "\"" "\\\"" commit "${commit}")

set(text "// Written by cmake/write_version.cmake at build time; do not edit.
#include \"app/build_commit.h\"

namespace clr {
const char* build_commit() { return \"${commit}\"; }
}  // namespace clr
")

set(old_text "")
if(EXISTS "${OUTPUT}")
    file(READ "${OUTPUT}" old_text)
endif()
if(NOT old_text STREQUAL text)
    file(WRITE "${OUTPUT}" "${text}")
endif()
