# Debian's libchipmunk-dev ships neither a CMake package nor a pkg-config file.
# Defines Chipmunk::Chipmunk.
find_path(Chipmunk_INCLUDE_DIR chipmunk/chipmunk.h)
find_library(Chipmunk_LIBRARY NAMES chipmunk)
if(Chipmunk_INCLUDE_DIR AND EXISTS "${Chipmunk_INCLUDE_DIR}/chipmunk/chipmunk.h")
  file(STRINGS "${Chipmunk_INCLUDE_DIR}/chipmunk/chipmunk.h" _cp_version
       REGEX "#define CP_VERSION_(MAJOR|MINOR|RELEASE) ")
  string(REGEX REPLACE ".*MAJOR ([0-9]+).*MINOR ([0-9]+).*RELEASE ([0-9]+).*" "\\1.\\2.\\3"
         Chipmunk_VERSION "${_cp_version}")
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Chipmunk
  REQUIRED_VARS Chipmunk_LIBRARY Chipmunk_INCLUDE_DIR VERSION_VAR Chipmunk_VERSION)
if(Chipmunk_FOUND AND NOT TARGET Chipmunk::Chipmunk)
  add_library(Chipmunk::Chipmunk UNKNOWN IMPORTED)
  set_target_properties(Chipmunk::Chipmunk PROPERTIES
    IMPORTED_LOCATION "${Chipmunk_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${Chipmunk_INCLUDE_DIR}")
endif()
mark_as_advanced(Chipmunk_INCLUDE_DIR Chipmunk_LIBRARY)
