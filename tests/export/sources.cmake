# SPDX-License-Identifier: MIT
set(RISE_TEST_EXPORT_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/test_clip.cpp)
