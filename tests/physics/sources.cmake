# SPDX-License-Identifier: MIT
set(RISE_TEST_PHYSICS_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/test_body.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_collide.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_contact_solver.cpp
  ${CMAKE_CURRENT_LIST_DIR}/joint_solver_tags.h
  ${CMAKE_CURRENT_LIST_DIR}/test_joint.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_joint_tree.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_world.cpp)
