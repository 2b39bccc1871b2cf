# Installs the runtime (and the format header it reads) as a CMake package, so that a game can
#   find_package(hullcook) ; target_link_libraries(game PRIVATE hullcook::runtime)
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
if(TARGET hullcook)
  install(TARGETS hullcook RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
