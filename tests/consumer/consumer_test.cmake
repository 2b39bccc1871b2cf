# cmake -DSOURCE_DIR=... -DWORK_DIR=... -DGENERATOR=... [-DSANITIZE=ON] -P consumer_test.cmake
file(REMOVE_RECURSE ${WORK_DIR})
set(flags "")
if(SANITIZE)
  set(flags "-fsanitize=address,undefined -fno-omit-frame-pointer")
endif()

function(run)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    string(REPLACE ";" " " printed "${ARGV}")
    message(FATAL_ERROR "failed (${status}): ${printed}")
  endif()
endfunction()

run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/runtime-build -G ${GENERATOR}
    -DCMAKE_BUILD_TYPE=Release
    -DHULLCOOK_BUILD_TOOL=OFF -DHULLCOOK_BUILD_TESTS=OFF -DHULLCOOK_BUILD_ADAPTERS=OFF
    -DHULLCOOK_BUILD_BENCHMARKS=OFF
    -DCMAKE_PROJECT_TOP_LEVEL_INCLUDES=${CMAKE_CURRENT_LIST_DIR}/no_packages.cmake
    -DCMAKE_CXX_FLAGS=${flags}
    -DCMAKE_INSTALL_PREFIX=${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/runtime-build)
run(${CMAKE_COMMAND} --install ${WORK_DIR}/runtime-build)
run(${CMAKE_COMMAND} -S ${CMAKE_CURRENT_LIST_DIR}/project -B ${WORK_DIR}/consumer-build
    -G ${GENERATOR} -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_CXX_FLAGS=${flags}
    -DCMAKE_EXE_LINKER_FLAGS=${flags})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/consumer-build)
run(${WORK_DIR}/consumer-build/consumer)

# The same consumer built by hand with the installed pkg-config file.
file(GLOB_RECURSE pc_file ${WORK_DIR}/prefix/hullcook-runtime.pc)
if(NOT pc_file)
  message(FATAL_ERROR "hullcook-runtime.pc was not installed under ${WORK_DIR}/prefix")
endif()
get_filename_component(pc_dir "${pc_file}" DIRECTORY)
set(ENV{PKG_CONFIG_PATH} ${pc_dir})
execute_process(COMMAND pkg-config --cflags --libs hullcook-runtime
                OUTPUT_VARIABLE pc_flags OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "pkg-config does not find hullcook-runtime under ${WORK_DIR}/prefix")
endif()
separate_arguments(pc_flags UNIX_COMMAND "${pc_flags}")
separate_arguments(sanitize UNIX_COMMAND "${flags}")
run(${CXX} -std=c++17 ${sanitize} ${CMAKE_CURRENT_LIST_DIR}/project/main.cpp ${pc_flags}
    -o ${WORK_DIR}/consumer-pkg-config)
run(${WORK_DIR}/consumer-pkg-config)
