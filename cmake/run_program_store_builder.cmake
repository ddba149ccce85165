# Runs clrender_build_program_store (cmake/build_program_store.cmake) so that nothing it meets
# fails the build: no OpenCL device, a driver that crashes. The store is then empty or short,
# which only makes first runs build from source, and a warning says so.
# PoCL's own kernel cache goes in the build tree, not the user's home.
set(ENV{POCL_CACHE_DIR} "${POCL_CACHE}")
set(arguments "${STORE}")
if(VARIANTS STREQUAL "all")
    list(APPEND arguments --all)
endif()
execute_process(COMMAND "${BUILDER}" ${arguments} RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    message(WARNING "clrender_build_program_store failed (${result}): the program store ${STORE} may be "
                    "incomplete; first runs build their programs from source")
endif()
file(REMOVE_RECURSE "${POCL_CACHE}")
