# Debian package of the command-line tool (the GUI joins it when ui/ exists).
set(CPACK_PACKAGE_NAME "linkwright")
set(CPACK_PACKAGE_VENDOR "Linkwright")
set(CPACK_PACKAGE_CONTACT "Linkwright developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_GENERATOR "DEB")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
include(CPack)
