# hullcook_add_bundle(TARGET <name> OUTPUT <game.hcb|.glb|.gltf|.json> INPUTS <image>...
#                     [BASE_DIR <dir>] [OPTIONS <hullcook cook option>...])
#
# Cooks each input into its own fragment with `hullcook cook INPUT -o X.hcf --depfile X.hcf.d`
# (one custom command each, so that Ninja or Make cooks them in parallel and re-cooks only an
# input whose image or physics sidecar changed) and links the fragments into OUTPUT with
# `hullcook link`. The target <name> builds OUTPUT (with ALL). Relative INPUTS are taken from the
# current source directory, a relative OUTPUT from the current binary directory. Each asset is
# named by its file name, or with BASE_DIR by its path relative to BASE_DIR, as
# `hullcook cook BASE_DIR` names the images of a folder; OUTPUT then has the same bytes.
# OPTIONS are passed to every cook (--tau 2 --ppu 32 ...). Each cook runs on one thread unless
# OPTIONS give --threads: the build tool runs the cooks side by side, and one sprite's own threads
# cost more to start than they save (docs/benchmarks.md). Fragments go to
# <current binary dir>/<name>.fragments/. Installed with the hullcook package: after
# find_package(hullcook), hullcook::hullcook is the cooker.
# The function keeps the policies it is defined with, whatever the calling project's minimum
# version: IN_LIST, cmake_path(), and (but for the cooks under Ninja, see there) depfiles made
# relative to the build tree for Ninja (CMP0116).
cmake_policy(PUSH)
cmake_policy(VERSION 3.20...3.25)
function(hullcook_add_bundle)
  cmake_parse_arguments(PARSE_ARGV 0 ARG "" "TARGET;OUTPUT;BASE_DIR" "INPUTS;OPTIONS")
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "hullcook_add_bundle: unknown arguments: ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  foreach(required TARGET OUTPUT INPUTS)
    if(NOT ARG_${required})
      message(FATAL_ERROR "hullcook_add_bundle: ${required} is required")
    endif()
  endforeach()
  if(TARGET hullcook::hullcook)
    set(tool hullcook::hullcook)
  elseif(TARGET hullcook)
    set(tool hullcook)
  else()
    message(FATAL_ERROR "hullcook_add_bundle: the hullcook cooker is not installed with this "
                        "package (it was built with HULLCOOK_BUILD_TOOL=OFF)")
  endif()
  cmake_path(ABSOLUTE_PATH ARG_OUTPUT BASE_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}" NORMALIZE)
  if(ARG_BASE_DIR)
    cmake_path(ABSOLUTE_PATH ARG_BASE_DIR BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" NORMALIZE)
  endif()
  set(threads --threads 1)
  foreach(option IN LISTS ARG_OPTIONS)
    if(option MATCHES "^--threads(=|$)")
      set(threads "")
    endif()
  endforeach()
  set(fragment_dir "${CMAKE_CURRENT_BINARY_DIR}/${ARG_TARGET}.fragments")
  set(fragments "")
  set(names "")
  foreach(input IN LISTS ARG_INPUTS)
    cmake_path(ABSOLUTE_PATH input BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" NORMALIZE
               OUTPUT_VARIABLE source)
    if(ARG_BASE_DIR)
      cmake_path(RELATIVE_PATH source BASE_DIRECTORY "${ARG_BASE_DIR}" OUTPUT_VARIABLE name)
      if(name MATCHES "^\\.\\./" OR name STREQUAL "..")
        message(FATAL_ERROR "hullcook_add_bundle: ${source} is not inside BASE_DIR ${ARG_BASE_DIR}")
      endif()
    else()
      cmake_path(GET source FILENAME name)
    endif()
    if(name IN_LIST names)
      message(FATAL_ERROR "hullcook_add_bundle: two inputs are named ${name}; give BASE_DIR")
    endif()
    list(APPEND names "${name}")
    set(fragment "${fragment_dir}/${name}.hcf")
    cmake_path(GET fragment PARENT_PATH directory)
    file(MAKE_DIRECTORY "${directory}")
    # Under Ninja the cook runs in the top build directory and names its output as Ninja does
    # (relative to it), so that Ninja reads the depfile as written: with CMP0116 CMake would run
    # `cmake -E cmake_transform_depfile` after every cook instead, a process of about 35 ms of CPU,
    # twice a small sprite's whole cook.
    set(output_argument "${fragment}")
    set(working_directory "${CMAKE_CURRENT_BINARY_DIR}")
    if(CMAKE_GENERATOR STREQUAL "Ninja")
      cmake_path(RELATIVE_PATH fragment BASE_DIRECTORY "${CMAKE_BINARY_DIR}"
                 OUTPUT_VARIABLE output_argument)
      set(working_directory "${CMAKE_BINARY_DIR}")
      cmake_policy(PUSH)
      cmake_policy(SET CMP0116 OLD)
    endif()
    add_custom_command(
      OUTPUT "${fragment}"
      COMMAND ${tool} cook "${source}" -o "${output_argument}" --name "${name}"
              --depfile "${fragment}.d" -q ${threads} ${ARG_OPTIONS}
      DEPENDS "${source}" "$<TARGET_FILE:${tool}>"
      DEPFILE "${fragment}.d"
      WORKING_DIRECTORY "${working_directory}"
      COMMENT "hullcook: cooking ${name}"
      VERBATIM)
    if(CMAKE_GENERATOR STREQUAL "Ninja")
      cmake_policy(POP)
    endif()
    list(APPEND fragments "${fragment}")
  endforeach()
  add_custom_command(
    OUTPUT "${ARG_OUTPUT}"
    COMMAND ${tool} link ${fragments} -o "${ARG_OUTPUT}" -q
    DEPENDS ${fragments} "$<TARGET_FILE:${tool}>"
    COMMENT "hullcook: linking ${ARG_OUTPUT}"
    VERBATIM)
  add_custom_target(${ARG_TARGET} ALL DEPENDS "${ARG_OUTPUT}")
endfunction()
cmake_policy(POP)
