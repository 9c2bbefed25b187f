# SPDX-License-Identifier: MIT
# External checks of the written files: the Khronos glTF-Validator (node) and a
# headless Blender import. Both read the synthetic samples that
# write_sample_clips makes; each is skipped, with its reason printed, only when
# its tool is not installed (scripts/deps.sh installs both).
add_executable(write_sample_clips ${CMAKE_CURRENT_LIST_DIR}/write_sample_clips.cpp
  ${CMAKE_CURRENT_LIST_DIR}/biped_fixture.h)
target_include_directories(write_sample_clips PRIVATE ${CMAKE_CURRENT_LIST_DIR}/.. ${PROJECT_SOURCE_DIR})
target_link_libraries(write_sample_clips PRIVATE rise_export nlohmann_json::nlohmann_json rise_options)

add_executable(compare_clips ${CMAKE_CURRENT_LIST_DIR}/compare_clips.cpp)
target_link_libraries(compare_clips PRIVATE rise_export rise_options)

set(RISE_EXPORT_SAMPLES ${CMAKE_CURRENT_BINARY_DIR}/export_samples)
add_test(NAME export.write_samples COMMAND write_sample_clips ${RISE_EXPORT_SAMPLES})
set_tests_properties(export.write_samples PROPERTIES FIXTURES_SETUP export_samples)

# A test that reports "skipped" with `message` (exit code 77).
function(rise_skipped_test name message)
  add_test(NAME ${name} COMMAND sh -c "echo '${message}'; exit 77")
  set_tests_properties(${name} PROPERTIES SKIP_RETURN_CODE 77)
endfunction()

find_program(RISE_NODE node)
if(RISE_NODE)
  add_test(NAME export.gltf_validator COMMAND ${RISE_NODE} ${PROJECT_SOURCE_DIR}/tools/validate_gltf.js
    ${RISE_EXPORT_SAMPLES}/sample.glb ${RISE_EXPORT_SAMPLES}/sample.gltf ${RISE_EXPORT_SAMPLES}/sample_in_place.glb
    ${RISE_EXPORT_SAMPLES}/sample_extract.glb ${RISE_EXPORT_SAMPLES}/sample_mixamo.glb
    ${RISE_EXPORT_SAMPLES}/sample_ue.glb ${RISE_EXPORT_SAMPLES}/sample_library.glb)
else()
  rise_skipped_test(export.gltf_validator "node is not installed: glTF-Validator check skipped (scripts/deps.sh installs it)")
endif()
set_tests_properties(export.gltf_validator PROPERTIES FIXTURES_REQUIRED export_samples LABELS gltf_validator)

# Cost measured on Debian 12 (Nov 2026): `apt-get install --no-install-recommends
# blender python3-numpy` = 171 packages, 173 MB of archives, 662 MB on disk,
# 51 s; the test itself takes about 4-6 s.
find_program(RISE_BLENDER blender)
if(RISE_BLENDER)
  # Blender runs on the system Python: no pyenv or virtualenv variables and no
  # shims on PATH, or its bundled add-ons load the wrong numpy.
  add_test(NAME export.blender_import
    COMMAND ${CMAKE_COMMAND} -E env --unset=PYTHONHOME --unset=PYTHONPATH --unset=PYENV_ROOT --unset=PYENV_VERSION
      --unset=VIRTUAL_ENV PATH=/usr/local/bin:/usr/bin:/bin
      ${RISE_BLENDER} -b --factory-startup --python-exit-code 1
      --python ${CMAKE_CURRENT_LIST_DIR}/blender_import.py -- ${RISE_EXPORT_SAMPLES})
  set_tests_properties(export.blender_import PROPERTIES TIMEOUT 300 FIXTURES_SETUP blender_roundtrip)
  add_test(NAME export.read_blender_glb
    COMMAND compare_clips ${RISE_EXPORT_SAMPLES}/sample.glb ${RISE_EXPORT_SAMPLES}/blender_roundtrip.glb)
  set_tests_properties(export.read_blender_glb PROPERTIES FIXTURES_REQUIRED blender_roundtrip LABELS blender)
else()
  rise_skipped_test(export.blender_import "blender is not installed: Blender import check skipped (scripts/deps.sh installs it)")
endif()
set_tests_properties(export.blender_import PROPERTIES FIXTURES_REQUIRED export_samples LABELS blender)
