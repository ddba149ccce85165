# Writes the man page clrender.1 from `clrender --help` with help2man, at build time:
#
#   cmake -DHELP2MAN=... -DPROGRAM=<clrender> -DVERSION_LINE="clrender 0.1.0" \
#         -DINCLUDE=<clrender.h2m> -DOUTPUT=<clrender.1> -P cmake/write_man_page.cmake
#
# help2man gets --version's first line from the project rather than from the program: the
# rest of --version names the commit and this machine's OpenCL platforms, which have no place
# in an installed page, and loading OpenCL at build time would tie the build to the driver (a
# sanitizer build, for one, checks the program it runs).

cmake_minimum_required(VERSION 3.21)  # this script runs alone (-P): give it the project's policies

execute_process(COMMAND "${HELP2MAN}" --no-info --no-discard-stderr "--version-string=${VERSION_LINE}"
                        "--include=${INCLUDE}" "--output=${OUTPUT}.tmp" "${PROGRAM}"
                RESULT_VARIABLE help2man_status ERROR_VARIABLE help2man_error)
if(NOT help2man_status EQUAL 0)
    message(FATAL_ERROR "help2man failed (${help2man_status}): ${help2man_error}")
endif()

# help2man knows ENVIRONMENT and EXAMPLES by their headings in --help, but not the exit
# codes' heading: make it the page's EXIT STATUS section rather than a part of ENVIRONMENT.
file(READ "${OUTPUT}.tmp" page)
string(REPLACE ".SS \"Exit status:\"" ".SH \"EXIT STATUS\"" page "${page}")
# An option's name on a line of its own, its description below, also when the name is shorter
# than the indent (`--plan`), where the formatter would start the description beside it.
string(REGEX REPLACE "\\.TP\n(\\\\fB\\\\-[^\n]*)\n" ".TP\n\\1\n.br\n" page "${page}")
file(WRITE "${OUTPUT}" "${page}")
file(REMOVE "${OUTPUT}.tmp")
