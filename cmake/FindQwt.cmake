# FindQwt: locates Qwt 6 built for the selected Qt major version.
#
# Provides the imported target Qwt::Qwt and sets Qwt_FOUND, Qwt_VERSION,
# Qwt_INCLUDE_DIR, Qwt_LIBRARY. Debian 12 ships Qwt 6.1.4 for Qt 5 as
# libqwt-qt5-dev (/usr/include/qwt, libqwt-qt5.so); a Qt 6 build is looked up
# under the qt6 names.

if(NOT DEFINED QT_VERSION_MAJOR)
  set(QT_VERSION_MAJOR 5)
endif()

find_path(Qwt_INCLUDE_DIR
  NAMES qwt_global.h
  PATH_SUFFIXES qwt qwt-qt${QT_VERSION_MAJOR} qt${QT_VERSION_MAJOR}/qwt)

find_library(Qwt_LIBRARY
  NAMES qwt-qt${QT_VERSION_MAJOR} qwt${QT_VERSION_MAJOR} qwt)

if(Qwt_INCLUDE_DIR AND EXISTS "${Qwt_INCLUDE_DIR}/qwt_global.h")
  file(STRINGS "${Qwt_INCLUDE_DIR}/qwt_global.h" _qwt_version_line
       REGEX "^#define[ \t]+QWT_VERSION_STR[ \t]+\"[0-9.]+\"")
  string(REGEX REPLACE ".*\"([0-9.]+)\".*" "\\1" Qwt_VERSION "${_qwt_version_line}")
endif()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Qwt
  REQUIRED_VARS Qwt_LIBRARY Qwt_INCLUDE_DIR
  VERSION_VAR Qwt_VERSION)

if(Qwt_FOUND AND NOT TARGET Qwt::Qwt)
  add_library(Qwt::Qwt UNKNOWN IMPORTED)
  set_target_properties(Qwt::Qwt PROPERTIES
    IMPORTED_LOCATION "${Qwt_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${Qwt_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "Qt${QT_VERSION_MAJOR}::Widgets;Qt${QT_VERSION_MAJOR}::Svg;Qt${QT_VERSION_MAJOR}::PrintSupport")
endif()

mark_as_advanced(Qwt_INCLUDE_DIR Qwt_LIBRARY)
