# The program store (device/program_store.h, docs/architecture.md, Program store): after
# clrender_build_program_store is built, it compiles render_packets for the feature sets a
# command line asks for into share/clrender/programs of the build tree, where the binary in the
# build tree finds it; `cmake --install` copies it beside the installed binary.
#
# CLRENDER_PROGRAM_STORE_VARIANTS: "common" (every scene's feature set in float precision with
# byte output, 38 programs), "all" (also --precision double and the float output of --alpha
# and EXR, 152), "none" (no store: first runs build from source).
set(CLRENDER_PROGRAM_STORE_VARIANTS "common" CACHE STRING "Programs built ahead of need: common, all or none")
set_property(CACHE CLRENDER_PROGRAM_STORE_VARIANTS PROPERTY STRINGS common all none)

include(GNUInstallDirs)
set(CLRENDER_PROGRAM_STORE_DIR "${CMAKE_BINARY_DIR}/share/clrender/programs")
if(CLRENDER_PROGRAM_STORE_VARIANTS STREQUAL "none")
    return()
endif()
# There even before the builder has run, so that an install never fails for want of it.
file(MAKE_DIRECTORY "${CLRENDER_PROGRAM_STORE_DIR}")
# Runs on every build: the builder keeps the entries that are still good and rebuilds what a
# new kernel or driver changed (a few hundred milliseconds when nothing did).
add_custom_target(clrender_program_store ALL
    COMMAND ${CMAKE_COMMAND} -DBUILDER=$<TARGET_FILE:clrender_build_program_store>
            -DSTORE=${CLRENDER_PROGRAM_STORE_DIR} -DVARIANTS=${CLRENDER_PROGRAM_STORE_VARIANTS}
            -DPOCL_CACHE=${CMAKE_BINARY_DIR}/program-store-pocl-cache
            -P ${CMAKE_SOURCE_DIR}/cmake/run_program_store_builder.cmake
    DEPENDS clrender_build_program_store
    COMMENT "Building the program store (render_packets ahead of need)"
    VERBATIM)
install(DIRECTORY "${CLRENDER_PROGRAM_STORE_DIR}/" DESTINATION ${CMAKE_INSTALL_DATADIR}/clrender/programs
        FILE_PERMISSIONS OWNER_READ OWNER_WRITE GROUP_READ WORLD_READ
        FILES_MATCHING REGEX "/[0-9a-f]+\\.clbin$")
