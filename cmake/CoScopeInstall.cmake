# SPDX-License-Identifier: GPL-3.0-or-later
# What `cmake --install` puts where (GNUInstallDirs), so CoScope starts like a desktop application:
# the two programs, the .desktop entry with the log formats it opens (shared-mime-info), the
# icon, AppStream metainfo, man pages and bash completion made from the programs' own --help
# (cmake/help-docs.sh; man pages need help2man, skipped without it), and the docs.
# The Debian package (cmake/CoScopePackage.cmake) installs exactly this under /usr.
include(GNUInstallDirs)
# The doc folder is named after the package, share/doc/coscope (unless set on the command line).
if("$CACHE{CMAKE_INSTALL_DOCDIR}" STREQUAL "")
  set(CMAKE_INSTALL_DOCDIR "${CMAKE_INSTALL_DATAROOTDIR}/doc/coscope")
endif()

set(_res ${CMAKE_SOURCE_DIR}/resources)
set(_out ${CMAKE_BINARY_DIR}/install-data)

install(TARGETS coscope coscope-cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# --- MIME types: resources/desktop/coscope.mime.xml is the one list ---------------------------
set(_mime_xml ${_res}/desktop/coscope.mime.xml)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${_mime_xml})
file(READ ${_mime_xml} _xml)
string(REGEX MATCHALL "<mime-type type=\"[^\"]+\"" _types "${_xml}")
list(TRANSFORM _types REPLACE "<mime-type type=\"([^\"]+)\"" "\\1")
list(JOIN _types ";" COSCOPE_DESKTOP_MIME_TYPES)
string(APPEND COSCOPE_DESKTOP_MIME_TYPES ";")
set(COSCOPE_METAINFO_MEDIATYPES "")
foreach(_t IN LISTS _types)
  string(APPEND COSCOPE_METAINFO_MEDIATYPES "    <mediatype>${_t}</mediatype>\n")
endforeach()
string(STRIP "${COSCOPE_METAINFO_MEDIATYPES}" COSCOPE_METAINFO_MEDIATYPES)
string(PREPEND COSCOPE_METAINFO_MEDIATYPES "    ")
install(FILES ${_mime_xml} DESTINATION ${CMAKE_INSTALL_DATADIR}/mime/packages RENAME ${COSCOPE_APP_ID}.xml)

# --- desktop entry, AppStream metainfo, icons -------------------------------------------------
configure_file(${_res}/desktop/coscope.desktop.in ${_out}/${COSCOPE_APP_ID}.desktop @ONLY)
configure_file(${_res}/desktop/coscope.metainfo.xml.in ${_out}/${COSCOPE_APP_ID}.metainfo.xml @ONLY)
install(FILES ${_out}/${COSCOPE_APP_ID}.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${_out}/${COSCOPE_APP_ID}.metainfo.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo)
file(GLOB _icons RELATIVE ${_res}/icons/hicolor ${_res}/icons/hicolor/*/apps/coscope.*)
foreach(_icon IN LISTS _icons)
  get_filename_component(_dir ${_icon} DIRECTORY)
  get_filename_component(_ext ${_icon} LAST_EXT)
  install(FILES ${_res}/icons/hicolor/${_icon}
    DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/${_dir} RENAME ${COSCOPE_APP_ID}${_ext})
endforeach()

# --- man pages and bash completion from the programs' --help --------------------------------
find_program(HELP2MAN_EXECUTABLE help2man)
if(NOT HELP2MAN_EXECUTABLE)
  message(STATUS "help2man not found: no man pages (scripts/setup.sh package installs it)")
endif()
set(_help_outputs "")
foreach(_program coscope coscope-cli)
  set(_outputs ${_out}/completions/${_program})
  if(HELP2MAN_EXECUTABLE)
    list(APPEND _outputs ${_out}/man/${_program}.1)
  endif()
  add_custom_command(OUTPUT ${_outputs}
    COMMAND ${CMAKE_SOURCE_DIR}/cmake/help-docs.sh $<TARGET_FILE:${_program}> ${_out} ${CMAKE_SOURCE_DIR} "${HELP2MAN_EXECUTABLE}"
    DEPENDS ${_program} ${CMAKE_SOURCE_DIR}/cmake/help-docs.sh ${CMAKE_SOURCE_DIR}/cmake/completion.bash.in
      ${CMAKE_SOURCE_DIR}/docs/man/${_program}.h2m
    COMMENT "Man page and bash completion of ${_program} from its --help"
    VERBATIM)
  list(APPEND _help_outputs ${_outputs})
  install(FILES ${_out}/completions/${_program} DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions)
  if(HELP2MAN_EXECUTABLE)
    install(FILES ${_out}/man/${_program}.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
  endif()
endforeach()
add_custom_target(coscope_help_docs ALL DEPENDS ${_help_outputs})

# --- documentation ---------------------------------------------------------------------------
install(FILES ${CMAKE_SOURCE_DIR}/README.md ${CMAKE_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(FILES ${_res}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR}/resources)
