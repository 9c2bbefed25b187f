// SPDX-License-Identifier: MIT
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include "base/assert.h"

namespace {

// A failed RISE_ASSERT inside a test fails that test instead of aborting the run.
void FailTestOnAssert(const char* expr, const char* file, int line, const char* msg) {
  ADD_FAIL_CHECK_AT(file, line, "RISE_ASSERT(" << expr << ") failed" << (msg ? ": " : "") << (msg ? msg : ""));
}

}  // namespace

int main(int argc, char** argv) {
  rise::SetAssertHandler(FailTestOnAssert);
  doctest::Context context(argc, argv);
  return context.run();
}
