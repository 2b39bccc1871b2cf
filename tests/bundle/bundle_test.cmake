# cmake -DBINARY_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DGENERATOR=... -P bundle_test.cmake
#
# Installs this build (the cooker included), configures tests/bundle/project against the install
# tree with find_package(hullcook), and checks what hullcook_add_bundle() promises: the bundle
# equals one `hullcook cook DIR`; a second build does nothing; touching one sprite, or one
# sprite's physics sidecar (known only from the depfile), re-cooks exactly that fragment and
# relinks.
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE ${WORK_DIR})

function(run)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 0)
    string(REPLACE ";" " " printed "${ARGV}")
    message(FATAL_ERROR "failed (${status}): ${printed}\n${out}")
  endif()
  set(output "${out}" PARENT_SCOPE)
endfunction()

set(samples ${SOURCE_DIR}/samples/sprites)
set(sprites ${WORK_DIR}/sprites)
file(MAKE_DIRECTORY ${sprites}/level)
file(COPY_FILE ${samples}/frozen-bubble__balls__bubble-1-mini.png ${sprites}/bubble.png)
file(COPY_FILE ${samples}/pingus__groundpieces__bridge__space__grid1.png ${sprites}/level/grid.png)
file(COPY_FILE ${samples}/pingus__groundpieces__ground__signposts__danger.png
     ${sprites}/level/danger.png)
file(WRITE ${sprites}/level/grid.physics.json "{\"density\": 3}")

run(${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${WORK_DIR}/prefix)
set(hullcook ${WORK_DIR}/prefix/bin/hullcook)
set(build ${WORK_DIR}/build)
run(${CMAKE_COMMAND} -S ${CMAKE_CURRENT_LIST_DIR}/project -B ${build} -G ${GENERATOR}
    -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DSPRITES_DIR=${sprites})

# Each fragment's cook runs on one thread (the build tool runs them side by side), as the
# project's OPTIONS give no --threads.
file(GLOB_RECURSE build_files ${build}/build.ninja ${build}/build.make)
set(cooks_on_one_thread 0)
foreach(build_file IN LISTS build_files)
  file(STRINGS ${build_file} lines REGEX "cook .*--depfile")
  foreach(line IN LISTS lines)
    if(NOT line MATCHES "-q --threads 1 --tau 1.5")
      message(FATAL_ERROR "a fragment's cook does not run on one thread: ${line}")
    endif()
    math(EXPR cooks_on_one_thread "${cooks_on_one_thread} + 1")
  endforeach()
endforeach()
if(cooks_on_one_thread LESS 3)
  message(FATAL_ERROR "found ${cooks_on_one_thread} cook commands in [${build_files}], not 3")
endif()

set(fragments bubble.png level/grid.png level/danger.png)
function(fragment_times out)
  set(times "")
  foreach(name IN LISTS fragments)
    file(TIMESTAMP ${build}/sprites.fragments/${name}.hcf time "%s%f")
    list(APPEND times "${time}")
  endforeach()
  set(${out} "${times}" PARENT_SCOPE)
endfunction()

# Builds and checks that exactly the fragments named in ARGN were cooked (by the build's output
# and by the fragments' times), and that the bundle was linked if any was.
function(build_and_expect_cooked)
  fragment_times(before)
  execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1.1)  # coarse file system clocks
  run(${CMAKE_COMMAND} --build ${build})
  fragment_times(after)
  string(REGEX MATCHALL "hullcook: cooking [^\r\n]*" cooked "${output}")
  string(REGEX MATCHALL "hullcook: linking" linked "${output}")
  list(TRANSFORM ARGN PREPEND "hullcook: cooking " OUTPUT_VARIABLE expected)
  list(SORT cooked)
  list(SORT expected)
  if(NOT cooked STREQUAL expected)
    message(FATAL_ERROR "expected to cook [${expected}], cooked [${cooked}]:\n${output}")
  endif()
  foreach(name time_before time_after IN ZIP_LISTS fragments before after)
    if(name IN_LIST ARGN AND time_before STREQUAL time_after AND time_before)
      message(FATAL_ERROR "${name}.hcf was not written again:\n${output}")
    elseif(NOT name IN_LIST ARGN AND NOT time_before STREQUAL time_after)
      message(FATAL_ERROR "${name}.hcf was written again:\n${output}")
    endif()
  endforeach()
  list(LENGTH ARGN count)
  list(LENGTH linked link_count)
  if((count GREATER 0) AND NOT (link_count EQUAL 1))
    message(FATAL_ERROR "expected one link:\n${output}")
  elseif((count EQUAL 0) AND NOT (link_count EQUAL 0))
    message(FATAL_ERROR "linked though nothing changed:\n${output}")
  endif()
endfunction()

function(expect_bundle_of_one_cook)
  run(${hullcook} cook ${sprites} -o ${WORK_DIR}/one.hcb -q --tau 1.5 --ppu 32 --lod 6)
  file(SHA256 ${WORK_DIR}/one.hcb one)
  file(SHA256 ${build}/game.hcb linked)
  if(NOT one STREQUAL linked)
    message(FATAL_ERROR "the linked bundle differs from one cook of ${sprites}")
  endif()
endfunction()

build_and_expect_cooked(${fragments})
expect_bundle_of_one_cook()
build_and_expect_cooked()
file(TOUCH ${sprites}/level/danger.png)
build_and_expect_cooked(level/danger.png)
file(WRITE ${sprites}/level/grid.physics.json "{\"density\": 4}")
build_and_expect_cooked(level/grid.png)
expect_bundle_of_one_cook()
build_and_expect_cooked()
