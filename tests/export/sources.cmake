# SPDX-License-Identifier: MIT
set(RISE_TEST_EXPORT_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/test_clip.cpp
  ${CMAKE_CURRENT_LIST_DIR}/biped_fixture.h
  ${CMAKE_CURRENT_LIST_DIR}/test_rotation_track.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_clip_resample.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_root_motion.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_joint_names.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_atomic_file.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_clip_metadata_json.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_gltf_writer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_gltf_reader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_bvh_writer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_bvh_reader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_bvh_reader_hostile.cpp
  ${CMAKE_CURRENT_LIST_DIR}/test_preview_sheet.cpp)
