# cmake -DSOURCE_DIR=... -DBUILD_DIR=... -DWORK_DIR=... -DGENERATOR=... [-DSANITIZE=ON]
#       -P components_test.cmake
# Installs the built tree to a temporary prefix and builds, against it, one consumer per
# component, each from the README's own example ("Using the runtime in a game": the CMake lines
# and the main.cpp under the <!-- consumer ... --> markers), then runs it on the cooked samples.
# Then checks what a game sees without an engine: the runtime alone still configures, and a
# component whose engine is missing fails with a message naming it.
file(REMOVE_RECURSE ${WORK_DIR})
set(flags "")
if(SANITIZE)
  set(flags "-fsanitize=address,undefined -fno-omit-frame-pointer")
endif()
set(prefix ${WORK_DIR}/prefix)
set(bundle ${SOURCE_DIR}/tests/formats/golden/v1.0/sprites.hcb)
set(asset teeworlds__skins__body__standard.png)

function(run)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 0)
    string(REPLACE ";" " " printed "${ARGV}")
    message(FATAL_ERROR "failed (${status}): ${printed}\n${out}")
  endif()
  message("${out}")
endfunction()

# The text of the fenced block that follows `<!-- consumer NAME -->` in the README.
file(READ ${SOURCE_DIR}/README.md readme)
function(readme_block name out)
  string(FIND "${readme}" "<!-- consumer ${name} -->" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "README.md has no <!-- consumer ${name} --> block")
  endif()
  string(SUBSTRING "${readme}" ${at} -1 rest)
  string(REGEX MATCH "```[a-z]*\n(.*)" fenced "${rest}")
  string(FIND "${CMAKE_MATCH_1}" "```" end)
  string(SUBSTRING "${CMAKE_MATCH_1}" 0 ${end} block)
  set(${out} "${block}" PARENT_SCOPE)
endfunction()

function(write_project dir cmake_lines)
  file(WRITE ${dir}/CMakeLists.txt
       "cmake_minimum_required(VERSION 3.25)\nproject(game LANGUAGES CXX)\n${cmake_lines}")
endfunction()

function(configure dir result output)
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${dir} -B ${dir}/build -G ${GENERATOR}
                          -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_FLAGS=${flags}
                          -DCMAKE_EXE_LINKER_FLAGS=${flags} ${ARGN}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  set(${result} ${status} PARENT_SCOPE)
  set(${output} "${out}" PARENT_SCOPE)
endfunction()

run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

readme_block("CMakeLists.txt" cmake_lines)
foreach(component box2d chipmunk)
  set(dir ${WORK_DIR}/${component})
  readme_block("${component} main.cpp" source)
  file(WRITE ${dir}/main.cpp "${source}")
  # The README's CMake lines are written for box2d and say "or chipmunk".
  string(REPLACE "box2d" "${component}" lines "${cmake_lines}")
  write_project(${dir} "${lines}")
  configure(${dir} status out)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "configuring the ${component} consumer failed:\n${out}")
  endif()
  run(${CMAKE_COMMAND} --build ${dir}/build)
  run(${dir}/build/game ${bundle} ${asset})
endforeach()

# No engine at all: the runtime alone still configures and builds.
set(dir ${WORK_DIR}/runtime)
file(WRITE ${dir}/main.cpp
     "#include <hullcook/runtime.h>\nint main() { return hullcook::runtime_version()[0] ? 0 : 1; }\n")
write_project(${dir} "find_package(hullcook REQUIRED)\nadd_executable(game main.cpp)
target_link_libraries(game PRIVATE hullcook::runtime)\n")
configure(${dir} status out -DCMAKE_DISABLE_FIND_PACKAGE_box2d=ON
          -DCMAKE_DISABLE_FIND_PACKAGE_Chipmunk=ON)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the runtime alone did not configure without the engines:\n${out}")
endif()
run(${CMAKE_COMMAND} --build ${dir}/build)
run(${dir}/build/game)

# An engine missing: the configure fails and says which component needs what.
foreach(case "box2d;box2d;needs Box2D 2.4" "chipmunk;Chipmunk;needs Chipmunk 7"
             "bullet;none;has no component 'bullet'")
  list(GET case 0 component)
  list(GET case 1 engine)
  list(GET case 2 expected)
  set(dir ${WORK_DIR}/missing_${component})
  file(WRITE ${dir}/main.cpp "int main() { return 0; }\n")
  write_project(${dir} "find_package(hullcook REQUIRED COMPONENTS ${component})\n")
  configure(${dir} status out -DCMAKE_DISABLE_FIND_PACKAGE_${engine}=ON)
  string(FIND "${out}" "${expected}" found)
  if(status EQUAL 0 OR found EQUAL -1)
    message(FATAL_ERROR "asking for ${component} without its engine gave (${status}):\n${out}")
  endif()
  message("as expected, without ${engine}: ${expected}")
endforeach()
