# Debian package: the CLI always; the GUI with its desktop entry, icon and AppStream data
# when it is built.
if(TARGET linkwright_ui)
  install(FILES ${CMAKE_CURRENT_LIST_DIR}/linkwright.desktop DESTINATION share/applications)
  install(FILES ${CMAKE_CURRENT_LIST_DIR}/io.github.linkwright.Linkwright.metainfo.xml DESTINATION share/metainfo)
  install(FILES ${PROJECT_SOURCE_DIR}/resources/icons/linkwright.svg
          DESTINATION share/icons/hicolor/scalable/apps)
endif()

set(CPACK_PACKAGE_NAME "linkwright")
set(CPACK_PACKAGE_VENDOR "Linkwright")
set(CPACK_PACKAGE_CONTACT "Linkwright developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_GENERATOR "DEB")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SECTION "science")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
include(CPack)
