# What `cmake --install build --prefix P` puts under P (README.md, Install): the two programs, the
# man page, the bash completion, the documentation with the licence, and the scene format's
# JSON Schema. The kernels are embedded in the binary, so nothing else is read at run time.

include(GNUInstallDirs)

install(TARGETS clrender clrender_make_forest RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# The man page is made from --help by help2man at build time, so it cannot drift from the
# options. Without help2man the build goes on and installs no man page.
find_program(HELP2MAN_PROGRAM help2man)
if(HELP2MAN_PROGRAM)
    set(CLRENDER_MAN_PAGE "${CMAKE_BINARY_DIR}/man/clrender.1")
    add_custom_command(
        OUTPUT "${CLRENDER_MAN_PAGE}"
        COMMAND ${CMAKE_COMMAND} -E make_directory "${CMAKE_BINARY_DIR}/man"
        COMMAND ${CMAKE_COMMAND} -DHELP2MAN=${HELP2MAN_PROGRAM} -DPROGRAM=$<TARGET_FILE:clrender>
                "-DVERSION_LINE=clrender ${PROJECT_VERSION}"
                -DINCLUDE=${CMAKE_SOURCE_DIR}/packaging/man/clrender.h2m -DOUTPUT=${CLRENDER_MAN_PAGE}
                -P ${CMAKE_SOURCE_DIR}/cmake/write_man_page.cmake
        DEPENDS clrender ${CMAKE_SOURCE_DIR}/packaging/man/clrender.h2m ${CMAKE_SOURCE_DIR}/cmake/write_man_page.cmake
        COMMENT "Writing the man page clrender.1 with help2man"
        VERBATIM)
    add_custom_target(clrender_man ALL DEPENDS "${CLRENDER_MAN_PAGE}")
    install(FILES "${CLRENDER_MAN_PAGE}" DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
else()
    message(WARNING "help2man not found (Debian: help2man): the install will have no man page")
endif()

install(FILES packaging/bash-completion/clrender DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions)
install(FILES README.md LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs FILES_MATCHING PATTERN "*.md" PATTERN "*.png")
install(FILES docs/scene.schema.json DESTINATION ${CMAKE_INSTALL_DATADIR}/clrender)
