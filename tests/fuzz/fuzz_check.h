// A check that stops a fuzz target with a message when a promise of the code under test is broken
// (libFuzzer then saves the input as a crash).
#pragma once

#include <cstdio>
#include <cstdlib>

// Aborts with "fuzz check failed: CONDITION: WHAT (file:line)" when condition is false; kept in
// every build type, unlike assert().
#define FUZZ_CHECK(condition, what)                                                           \
  do {                                                                                        \
    if (!(condition)) {                                                                       \
      std::fprintf(stderr, "fuzz check failed: %s: %s (%s:%d)\n", #condition, what, __FILE__, \
                   __LINE__);                                                                 \
      std::abort();                                                                           \
    }                                                                                         \
  } while (false)
