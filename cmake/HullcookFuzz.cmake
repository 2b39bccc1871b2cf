# The libFuzzer build (scripts/fuzz, build/fuzz): clang's coverage instrumentation on every
# library so that the fuzzer sees their branches, AddressSanitizer + UndefinedBehaviorSanitizer,
# and the targets of tests/fuzz. Included only with HULLCOOK_FUZZ=ON; the normal builds never see it.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "HULLCOOK_FUZZ needs clang with libFuzzer (scripts/fuzz uses clang++-14)")
endif()
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
                    -fno-sanitize-recover=all -g)
add_link_options(-fsanitize=address,undefined)

# Warnings are errors in the GCC builds, which police them; clang-14 here reports a few more
# (e.g. -Wunused-lambda-capture) that must not stop the fuzzing.
function(hullcook_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra)
endfunction()
