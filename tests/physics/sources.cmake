# SPDX-License-Identifier: MIT
set(RISE_TEST_PHYSICS_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/test_collide.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_placeholder_physics.cpp)
