// Invariant checks for the fuzz targets. A broken invariant must stop the run
// with a crash that libFuzzer records (it saves the input as crash-*), and
// the message says which invariant, since a bare abort() would not.
#pragma once

#include <cstdio>
#include <cstdlib>

#define FUZZ_CHECK(condition, ...)                                                   \
    do {                                                                             \
        if (!(condition)) {                                                          \
            std::fprintf(stderr, "fuzz invariant broken (%s:%d): %s\n  ", __FILE__,  \
                         __LINE__, #condition);                                      \
            std::fprintf(stderr, __VA_ARGS__);                                       \
            std::fprintf(stderr, "\n");                                              \
            std::abort();                                                            \
        }                                                                            \
    } while (0)
