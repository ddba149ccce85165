# Writes the man page clrender.1 from `clrender --help` with help2man, at build time:
#
#   cmake -DHELP2MAN=... -DPROGRAM=<clrender> -DINCLUDE=<clrender.h2m> -DOUTPUT=<clrender.1> \
#         -P cmake/write_man_page.cmake
#
# Only the first line of --version ("clrender 0.1.0") is given to help2man: the rest names the
# commit and this machine's OpenCL platforms, which have no place in an installed page.

cmake_minimum_required(VERSION 3.21)  # this script runs alone (-P): give it the project's policies

execute_process(COMMAND "${PROGRAM}" --version
                RESULT_VARIABLE version_status OUTPUT_VARIABLE version_text ERROR_VARIABLE version_error)
if(NOT version_status EQUAL 0)
    message(FATAL_ERROR "${PROGRAM} --version failed (${version_status}): ${version_error}")
endif()
string(REGEX REPLACE "\n.*" "" version_line "${version_text}")

execute_process(COMMAND "${HELP2MAN}" --no-info --no-discard-stderr "--version-string=${version_line}"
                        "--include=${INCLUDE}" "--output=${OUTPUT}.tmp" "${PROGRAM}"
                RESULT_VARIABLE help2man_status ERROR_VARIABLE help2man_error)
if(NOT help2man_status EQUAL 0)
    message(FATAL_ERROR "help2man failed (${help2man_status}): ${help2man_error}")
endif()

# help2man knows ENVIRONMENT and EXAMPLES by their headings in --help, but not the exit
# codes' heading: make it the page's EXIT STATUS section rather than a part of ENVIRONMENT.
file(READ "${OUTPUT}.tmp" page)
string(REPLACE ".SS \"Exit status:\"" ".SH \"EXIT STATUS\"" page "${page}")
file(WRITE "${OUTPUT}" "${page}")
file(REMOVE "${OUTPUT}.tmp")
