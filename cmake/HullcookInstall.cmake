# Installs the runtime (and the format header it reads) as a CMake package, so that a game can
#   find_package(hullcook) ; target_link_libraries(game PRIVATE hullcook::runtime)
# and, when the adapters are built, its components box2d and chipmunk:
#   find_package(hullcook REQUIRED COMPONENTS box2d) ; ... hullcook::box2d
# Each component has an export set of its own, loaded by the config file only after it has found
# that component's engine. A pkg-config file covers the runtime for other build systems. Where
# the cooker is built, a game's build cooks its sprites with hullcook_add_bundle().
include(CMakePackageConfigHelpers)
set(hullcook_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/hullcook)
install(TARGETS hullcook_formats hullcook_runtime EXPORT hullcookTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY formats/include/ runtime/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT hullcookTargets NAMESPACE hullcook:: FILE hullcookTargets.cmake
        DESTINATION ${hullcook_cmake_dir})
foreach(engine box2d chipmunk)
  if(TARGET hullcook_${engine})
    install(TARGETS hullcook_${engine} EXPORT hullcook_${engine}Targets
            ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
    install(FILES runtime/adapters/include/hullcook/${engine}.h
            DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/hullcook)
    install(EXPORT hullcook_${engine}Targets NAMESPACE hullcook::
            FILE hullcook_${engine}Targets.cmake DESTINATION ${hullcook_cmake_dir})
  endif()
endforeach()
if(TARGET hullcook_chipmunk)
  # Debian's Chipmunk has no package file of its own: the config file finds it with ours.
  install(FILES cmake/FindChipmunk.cmake DESTINATION ${hullcook_cmake_dir})
endif()
configure_package_config_file(cmake/hullcookConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/hullcookConfig.cmake
  INSTALL_DESTINATION ${hullcook_cmake_dir})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/hullcookConfigVersion.cmake
  COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/hullcookConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/hullcookConfigVersion.cmake
        DESTINATION ${hullcook_cmake_dir})

# The prefix relative to the .pc file, so that `cmake --install --prefix` anywhere stays right.
file(RELATIVE_PATH hullcook_pc_to_prefix
     /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
configure_file(cmake/hullcook-runtime.pc.in ${CMAKE_CURRENT_BINARY_DIR}/hullcook-runtime.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/hullcook-runtime.pc
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
# The cooker, when built, as hullcook::hullcook, with hullcook_add_bundle() to run it from a
# game's build (cmake/HullcookBundle.cmake).
if(TARGET hullcook)
  install(TARGETS hullcook EXPORT hullcookToolTargets RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  # Found by the cooker at bin/../lib/hullcook (tool/cook/src/draco_module.cpp): not LIBDIR,
  # which may be lib/<triplet>.
  install(TARGETS hullcook_draco LIBRARY DESTINATION lib/hullcook)
  install(EXPORT hullcookToolTargets NAMESPACE hullcook:: FILE hullcookToolTargets.cmake
          DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hullcook)
endif()
install(FILES cmake/HullcookBundle.cmake DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hullcook)
