// SPDX-License-Identifier: MIT
#include "base/assert.h"

#include <cstdio>
#include <cstdlib>

namespace rise {
namespace {

void DefaultHandler(const char* expr, const char* file, int line, const char* msg) {
  std::fprintf(stderr, "rise-gen internal error: %s:%d: assertion '%s' failed%s%s\n", file, line, expr,
               msg ? ": " : "", msg ? msg : "");
  std::abort();
}

AssertHandler gHandler = DefaultHandler;

}  // namespace

AssertHandler SetAssertHandler(AssertHandler handler) {
  AssertHandler previous = gHandler;
  gHandler = handler ? handler : DefaultHandler;
  return previous;
}

void AssertFailed(const char* expr, const char* file, int line, const char* msg) {
  gHandler(expr, file, line, msg);
}

}  // namespace rise
