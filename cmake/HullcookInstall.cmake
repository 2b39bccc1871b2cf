# Installs the runtime (and the format header it reads) as a CMake package, so that a game can
#   find_package(hullcook) ; target_link_libraries(game PRIVATE hullcook::runtime)
# and, where the cooker is built, cook its sprites with hullcook_add_bundle().
include(CMakePackageConfigHelpers)
install(TARGETS hullcook_formats hullcook_runtime EXPORT hullcookTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY formats/include/ runtime/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT hullcookTargets NAMESPACE hullcook:: FILE hullcookTargets.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hullcook)
configure_package_config_file(cmake/hullcookConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/hullcookConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hullcook)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/hullcookConfigVersion.cmake
  COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/hullcookConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/hullcookConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hullcook)
# The cooker, when built, as hullcook::hullcook, with hullcook_add_bundle() to run it from a
# game's build (cmake/HullcookBundle.cmake).
if(TARGET hullcook)
  install(TARGETS hullcook EXPORT hullcookToolTargets RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(EXPORT hullcookToolTargets NAMESPACE hullcook:: FILE hullcookToolTargets.cmake
          DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hullcook)
endif()
install(FILES cmake/HullcookBundle.cmake DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hullcook)
