# bench_cook: the cook against the speed of decoding (issue 17). It writes its synthetic images
# with libpng and libwebp, measures their decoders alone, and starts the hullcook executable.
target_link_libraries(bench_cook PRIVATE PNG::PNG PkgConfig::WebP)
target_compile_definitions(bench_cook PRIVATE HULLCOOK_EXE="$<TARGET_FILE:hullcook>")
add_dependencies(bench_cook hullcook)
