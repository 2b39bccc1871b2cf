# bench_runtime: the loader and the Box2D adapter (see bench_runtime.cpp).
target_link_libraries(bench_runtime PRIVATE hullcook_runtime)
if(TARGET hullcook_box2d)
  target_link_libraries(bench_runtime PRIVATE hullcook_box2d)
  target_compile_definitions(bench_runtime PRIVATE HULLCOOK_BENCH_BOX2D=1)
endif()
target_include_directories(bench_runtime PRIVATE ${PROJECT_SOURCE_DIR}/tests/formats)
