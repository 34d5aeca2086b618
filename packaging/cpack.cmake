# The Debian package (cpack -G DEB in a Release build): the CLI always; the GUI with its
# desktop entry, MIME type, icon and AppStream data when it is built; manual pages made
# from each program's --help; the copyright file and changelog Debian policy asks for.
# packaging/check-package.sh runs lintian on the result and installs it in a fresh root.

set(LINKWRIGHT_MAINTAINER "Linkwright maintainers <maintainers@users.noreply.h-seed-abf66869.example>"
  CACHE STRING "Debian package maintainer, as 'Name <address>'")
set(linkwright_doc_dir share/doc/linkwright)

# The changelog's newest entry must be the version being packaged.
file(STRINGS ${CMAKE_CURRENT_LIST_DIR}/changelog changelog_head LIMIT_COUNT 1)
if(NOT changelog_head MATCHES "^linkwright \\(${PROJECT_VERSION}\\) ")
  message(FATAL_ERROR "packaging/changelog starts with '${changelog_head}': add an entry for ${PROJECT_VERSION}")
endif()

# Debian wants documentation compressed with gzip -9n (no name or time stamp: reproducible).
find_program(GZIP_EXECUTABLE gzip REQUIRED)
function(linkwright_gzip source output)
  add_custom_command(OUTPUT ${output}
    COMMAND ${GZIP_EXECUTABLE} -9nc ${source} > ${output}
    DEPENDS ${source} VERBATIM)
endfunction()

set(packaging_out ${PROJECT_BINARY_DIR}/packaging)
file(MAKE_DIRECTORY ${packaging_out})
linkwright_gzip(${CMAKE_CURRENT_LIST_DIR}/changelog ${packaging_out}/changelog.gz)

# Manual pages from --help, so they never drift from the programs.
find_program(HELP2MAN_EXECUTABLE help2man)
if(NOT HELP2MAN_EXECUTABLE)
  message(FATAL_ERROR "help2man not found: packaging/install-deps.sh installs it (the manual pages are made from --help)")
endif()
set(manpages)
function(linkwright_manpage target summary)
  set(page ${packaging_out}/${target}.1)
  add_custom_command(OUTPUT ${page}
    # In the C locale help2man would write the help's '−' and '°' as '???'.
    COMMAND ${CMAKE_COMMAND} -E env LC_ALL=C.UTF-8 ${HELP2MAN_EXECUTABLE} --locale=C.UTF-8 --no-info --section=1 --name=${summary}
            --include=${CMAKE_CURRENT_FUNCTION_LIST_DIR}/manpage.h2m --output=${page} $<TARGET_FILE:${target}>
    DEPENDS ${target} ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/manpage.h2m VERBATIM)
  linkwright_gzip(${page} ${page}.gz)
  set(manpages ${manpages} ${page}.gz PARENT_SCOPE)
endfunction()
linkwright_manpage(linkwright-cli "analyse planar linkages from the command line")
if(TARGET linkwright)
  linkwright_manpage(linkwright "design and analyse planar linkages in a window")
endif()
add_custom_target(linkwright_package_files ALL DEPENDS ${manpages} ${packaging_out}/changelog.gz)

install(FILES ${manpages} DESTINATION share/man/man1)
install(FILES ${packaging_out}/changelog.gz ${CMAKE_CURRENT_LIST_DIR}/copyright DESTINATION ${linkwright_doc_dir})
if(TARGET linkwright)
  install(FILES ${CMAKE_CURRENT_LIST_DIR}/linkwright.desktop DESTINATION share/applications)
  install(FILES ${CMAKE_CURRENT_LIST_DIR}/io.github.linkwright.linkwright.metainfo.xml DESTINATION share/metainfo)
  install(FILES ${CMAKE_CURRENT_LIST_DIR}/linkwright-mime.xml DESTINATION share/mime/packages RENAME linkwright.xml)
  install(FILES ${PROJECT_SOURCE_DIR}/resources/icons/linkwright.svg DESTINATION share/icons/hicolor/scalable/apps)
endif()

# A package is built for the Debian release it is built on: its dependencies carry that
# release's library names (Debian 13's have the t64 suffixes), so the release is part of its
# version: 0.1.0+deb12 for Debian 12, 0.1.0+deb13 for Debian 13, which also sorts the newer
# release's package above the older one's across an upgrade.
cmake_host_system_information(RESULT linkwright_distribution QUERY DISTRIB_ID)
cmake_host_system_information(RESULT linkwright_distribution_version QUERY DISTRIB_VERSION_ID)
if(linkwright_distribution STREQUAL "debian" AND linkwright_distribution_version MATCHES "^[0-9]+$")
  set(linkwright_package_suffix "+deb${linkwright_distribution_version}")
else()
  set(linkwright_package_suffix "")
endif()

set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGE_NAME "linkwright")
set(CPACK_PACKAGE_VENDOR "The Linkwright developers")
set(CPACK_PACKAGE_CONTACT "${LINKWRIGHT_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "design and analyse planar linkages")
set(CPACK_PACKAGE_DESCRIPTION_FILE ${CMAKE_CURRENT_LIST_DIR}/description.txt)
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_STRIP_FILES ON)
set(CPACK_INSTALL_DEFAULT_DIRECTORY_PERMISSIONS
  OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
set(CPACK_DEBIAN_PACKAGE_VERSION "${PROJECT_VERSION}${linkwright_package_suffix}")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION "science")
set(CPACK_DEBIAN_PACKAGE_PRIORITY "optional")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The lab report's font (θ, ω, α, μ, ²) is found by fontconfig at run time, unseen by shlibdeps;
# libcairo2's fontconfig only needs some font, not this one.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "fonts-dejavu-core")
if(TARGET linkwright)
  # Qt loads its window-system plugins at run time, so shlibdeps cannot see them; libqt6gui6
  # only recommends them and the offscreen one alone cannot open a window.
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "${CPACK_DEBIAN_PACKAGE_DEPENDS}, qt6-qpa-plugins")
endif()
if(LINKWRIGHT_PYTHON_DEPENDS)
  # import linkwright (python/CMakeLists.txt): its interpreter version and NumPy, which
  # dpkg-shlibdeps cannot see (an extension links no libpython).
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "${CPACK_DEBIAN_PACKAGE_DEPENDS}, ${LINKWRIGHT_PYTHON_DEPENDS}")
  # linkwright.batch imports Dask only when called: the module works without it.
  set(CPACK_DEBIAN_PACKAGE_SUGGESTS "python3-distributed")
endif()
include(CPack)
