// SPDX-License-Identifier: MIT
// Programmer-error checks (tier 1 of the three error tiers; see README "Errors").
#pragma once

namespace rise {

// Called when a RISE_ASSERT fails. The default prints the expression and
// location to stderr and aborts; tests install a handler that fails the test.
using AssertHandler = void (*)(const char* expr, const char* file, int line, const char* msg);

// Installs a handler and returns the previous one. Passing nullptr restores the default.
AssertHandler SetAssertHandler(AssertHandler handler);

// Reports a failed assertion through the current handler.
void AssertFailed(const char* expr, const char* file, int line, const char* msg);

}  // namespace rise

// Kept in release builds: the checks are cheap next to a simulation step and a
// violated invariant must never silently produce a broken clip.
#define RISE_ASSERT(cond) \
  ((cond) ? (void)0 : ::rise::AssertFailed(#cond, __FILE__, __LINE__, nullptr))
#define RISE_ASSERT_MSG(cond, msg) \
  ((cond) ? (void)0 : ::rise::AssertFailed(#cond, __FILE__, __LINE__, (msg)))
