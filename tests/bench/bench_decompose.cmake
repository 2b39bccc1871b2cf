# bench_decompose: the comparisons with Chipmunk's and CGAL's convex decompositions. Both are
# optional benchmark-only dependencies: without them the comparison tables say "not built".
if(TARGET Chipmunk::Chipmunk)
  target_link_libraries(bench_decompose PRIVATE Chipmunk::Chipmunk)
  target_compile_definitions(bench_decompose PRIVATE HULLCOOK_BENCH_CHIPMUNK=1)
endif()
set(CGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE TRUE)
find_package(CGAL QUIET)
if(CGAL_FOUND)
  target_link_libraries(bench_decompose PRIVATE CGAL::CGAL)
  target_compile_definitions(bench_decompose PRIVATE HULLCOOK_BENCH_CGAL=1)
endif()
# Its tables beyond Google Benchmark's: the authors' code (table A), the first run (table D);
# its figures' plots.
target_sources(bench_decompose PRIVATE
  ${CMAKE_CURRENT_SOURCE_DIR}/paper_models.cpp ${CMAKE_CURRENT_SOURCE_DIR}/authors_comparison.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/first_run.cpp ${CMAKE_CURRENT_SOURCE_DIR}/child_process.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/svg_plot.cpp)
