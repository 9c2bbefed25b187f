# SPDX-License-Identifier: MIT
set(RISE_TEST_CORE_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/test_biped_def.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_input_json.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_input_schema.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_biped.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_point_mass_plan.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_body_pose_ik.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_generate.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_clip_output.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_clip_quality.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_library_manifest.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_batch_runner.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_spec_overrides.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_clip_check.cpp)
