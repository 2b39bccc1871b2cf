# Injected with CMAKE_PROJECT_TOP_LEVEL_INCLUDES: any find_package() call fails the configure,
# which proves the runtime-only build needs no third-party package.
macro(hullcook_refuse_packages method name)
  message(FATAL_ERROR "runtime-only build called find_package(${name})")
endmacro()
cmake_language(SET_DEPENDENCY_PROVIDER hullcook_refuse_packages SUPPORTED_METHODS FIND_PACKAGE)
