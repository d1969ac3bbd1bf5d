/* Checks for the C test programs of the C API: CHECK counts a failure and goes
 * on; CHECK_OK returns 1 from main when a call fails, printing its status and
 * message. Each program defines `static int failures`. */
#ifndef PRISM_TESTS_C_CHECK_H
#define PRISM_TESTS_C_CHECK_H

#include <stdio.h>

#include "prism.h"

#define CHECK(cond)                                                                \
  do {                                                                             \
    if (!(cond)) {                                                                 \
      fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond);     \
      ++failures;                                                                  \
    }                                                                              \
  } while (0)

#define CHECK_OK(call)                                                                                    \
  do {                                                                                                    \
    PrismStatus s_ = (call);                                                                              \
    if (s_ != PRISM_OK) {                                                                                 \
      fprintf(stderr, "%s:%d: %s returned %s: %s\n", __FILE__, __LINE__, #call, prismStatusName(s_),       \
              prismGetLastError());                                                                       \
      return 1;                                                                                           \
    }                                                                                                     \
  } while (0)

#endif
