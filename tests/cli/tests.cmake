# SPDX-License-Identifier: MIT
# CTest cases that run the rise-gen binary end to end: every command, every exit code, the
# error messages of bad input (with no output file left behind), and batch determinism,
# resume and sharding. Clips are kept short (max_duration_s 2) so the cases stay fast; such a
# clip cannot stand yet, so it exits 1 while still writing its files.
set(RISE_CLI_DIR ${CMAKE_CURRENT_LIST_DIR})
set(RISE_CLI_WORK ${CMAKE_CURRENT_BINARY_DIR}/cli_work)
set(RISE_SAMPLES ${PROJECT_SOURCE_DIR}/samples)

add_executable(write_check_fixture ${RISE_CLI_DIR}/write_check_fixture.cpp)
target_include_directories(write_check_fixture PRIVATE ${CMAKE_CURRENT_LIST_DIR}/.. ${PROJECT_SOURCE_DIR})
target_link_libraries(write_check_fixture PRIVATE rise_export rise_options)

add_test(NAME cli.version COMMAND rise-gen --version)
set_tests_properties(cli.version PROPERTIES PASS_REGULAR_EXPRESSION "^[0-9]+\\.[0-9]+\\.[0-9]+")

# rise_cli_test(name EXIT code REGEX regex ARGS a b ... [PRESENT f ...] [ABSENT f ...] [SETUP a b ...]
#               [EMPTY_STDOUT] [STDOUT_FILE f])
# runs `rise-gen ARGS` in an empty folder of its own and checks the exit code, the output
# (PASS_REGULAR_EXPRESSION) and which files exist afterwards (expect.cmake).
function(rise_cli_test name)
  cmake_parse_arguments(T "EMPTY_STDOUT" "EXIT;REGEX;STDOUT_FILE" "ARGS;PRESENT;ABSENT;SETUP" ${ARGN})
  string(REPLACE ";" "|" args "$<TARGET_FILE:rise-gen>;${T_ARGS}")
  set(defs -DCOMMAND=${args} -DWORKDIR=${RISE_CLI_WORK}/${name} -DEXIT=${T_EXIT})
  foreach(list PRESENT ABSENT SETUP)
    if(T_${list})
      string(REPLACE ";" "|" joined "${T_${list}}")
      list(APPEND defs -D${list}=${joined})
    endif()
  endforeach()
  if(T_EMPTY_STDOUT)
    list(APPEND defs -DEMPTY_STDOUT=1)
  endif()
  if(T_STDOUT_FILE)
    list(APPEND defs -DSTDOUT_FILE=${T_STDOUT_FILE})
  endif()
  add_test(NAME cli.${name} COMMAND ${CMAKE_COMMAND} ${defs} -P ${RISE_CLI_DIR}/expect.cmake)
  set_tests_properties(cli.${name} PROPERTIES PASS_REGULAR_EXPRESSION "${T_REGEX}"
    FAIL_REGULAR_EXPRESSION "RISE_EXPECT_FAILED" LABELS cli)
endfunction()

# --- help and schema (exit 0) ---
rise_cli_test(help EXIT 0 REGEX "Subcommands:.*generate.*batch.*check.*preview.*schema.*Exit codes" ARGS --help)
rise_cli_test(no_command EXIT 2 REGEX "Usage: rise-gen" ARGS)
foreach(command generate batch check preview schema)
  rise_cli_test(help_${command} EXIT 0 REGEX "Usage: rise-gen ${command}" ARGS ${command} --help)
endforeach()
rise_cli_test(schema EXIT 0 REGEX "\"\\$schema\": \"https://json-schema.org/draft/2020-12/schema\""
  ARGS schema STDOUT_FILE ${PROJECT_SOURCE_DIR}/schema/rise-input.schema.json)

# --- generate: a clip too short to stand is written and exits 1 ---
rise_cli_test(generate_short_clip EXIT 1
  REGEX "supine.json -> c.glb, c.bvh: did not stand within 2.0 s.*2.00 s, 61 frames at 30 fps; quality FAIL \\(.*ends standing"
  ARGS ${RISE_SAMPLES}/supine.json -o c.glb -o c.bvh --max-duration 2 --trace t.jsonl --preview p.png
  PRESENT c.glb c.bvh c.meta.json t.jsonl p.png)
rise_cli_test(generate_subcommand_overrides EXIT 1 REGEX "1.00 s, 61 frames at 60 fps"
  ARGS generate ${RISE_SAMPLES}/prone.json -o c.gltf --max-duration 1 --fps 60 --seed 9 --names ue --in-place
  PRESENT c.gltf c.bin c.meta.json)
rise_cli_test(generate_json EXIT 1 REGEX "\"stood\": false.*\"quality\": {.*\"passed\": false"
  ARGS ${RISE_SAMPLES}/side.json -o c.glb --max-duration 1 --json --root-motion extract PRESENT c.glb)
rise_cli_test(generate_quiet EXIT 1 REGEX "stdout: \nstderr: \n" ARGS ${RISE_SAMPLES}/supine.json -o c.bvh --max-duration 1 -q
  --bvh-units cm --bvh-up z EMPTY_STDOUT PRESENT c.bvh)
# Exit 0 needs a clip that stands and passes every quality bar: the main
# promise, so it runs the full sample the README's main command runs.
rise_cli_test(generate_stands EXIT 0 REGEX "stood at [0-9.]+ s.*quality PASS"
  ARGS ${RISE_SAMPLES}/prone.json -o c.glb PRESENT c.glb)
set_tests_properties(cli.generate_stands PROPERTIES LABELS "cli;controller")

# --- bad input: exit 2, one message naming file, path, found and allowed; no file written ---
set(no_output ABSENT c.glb c.meta.json)
function(rise_bad_input name regex)
  rise_cli_test(bad_${name} EXIT 2 REGEX "${regex}" ARGS ${ARGN} ${no_output})
endfunction()
set(bad ${RISE_CLI_DIR}/bad)
rise_bad_input(syntax "syntax.json:2:35: invalid JSON: syntax error" ${bad}/syntax.json -o c.glb)
rise_bad_input(unknown_key "unknown_key.json: strat: unknown key \"strat\", did you mean \"start\"\\?"
  ${bad}/unknown_key.json -o c.glb)
rise_bad_input(posture "start.posture: found \"sitting\", allowed: supine, prone, side_left, side_right, custom"
  ${bad}/bad_posture.json -o c.glb)
rise_bad_input(range "character.height_m: found 3.1, allowed: 1.2 to 2.3 m" ${bad}/height_range.json -o c.glb)
rise_bad_input(type "fps: found \"fast\" \\(a string\\), allowed: a number from 1 to 240" ${bad}/fps_type.json -o c.glb)
rise_bad_input(duplicate_key "seed: found this key twice in the same object" ${bad}/duplicate_key.json -o c.glb)
rise_bad_input(fraction "seed: found 1.5, allowed: a whole number" ${bad}/seed_fraction.json -o c.glb)
rise_bad_input(missing_key "disturbances\\[0\\]: missing key \"duration_s\"" ${bad}/disturbance_missing.json -o c.glb)
rise_bad_input(joint_word "start.joints_deg.knee_l: unknown joint \"knee_l\".*did you mean \"shin_l\"" ${bad}/joint_word.json -o c.glb)
rise_bad_input(consistency "disturbances\\[0\\].time_s: found 5, allowed: 0 to max_duration_s" ${bad}/disturbance_late.json -o c.glb)
rise_bad_input(missing_file "nowhere.json: cannot open the file for reading" nowhere.json -o c.glb)
rise_bad_input(option_range "command line: --fps: found 500, allowed: 1 to 240" ${RISE_SAMPLES}/supine.json -o c.glb --fps 500)
rise_bad_input(option_names "command line: --names: found \"bogus\".*allowed: default, mixamo, ue" ${RISE_SAMPLES}/supine.json -o c.glb --names bogus)
rise_bad_input(option_consistency "command line: disturbances\\[0\\].time_s: found 4, allowed: 0 to max_duration_s \\(2 s\\)"
  ${RISE_SAMPLES}/push.json -o c.glb --max-duration 2)
rise_bad_input(option_choice "--root-motion: sideways not in {bake,in-place,extract}" ${RISE_SAMPLES}/supine.json -o c.glb --root-motion sideways)
rise_bad_input(unknown_option "argument was not expected: --frobnicate" ${RISE_SAMPLES}/supine.json -o c.glb --frobnicate)
rise_bad_input(no_output "--output is required" ${RISE_SAMPLES}/supine.json)
rise_bad_input(extension "c.fbx: found the extension '.fbx', allowed: .glb, .gltf, .bvh" ${RISE_SAMPLES}/supine.json -o c.glb -o c.fbx)
rise_bad_input(folder "nodir/c.glb: folder 'nodir' does not exist" ${RISE_SAMPLES}/supine.json -o c.glb -o nodir/c.glb)
rise_bad_input(preview_folder "nodir/p.png: folder 'nodir' does not exist" ${RISE_SAMPLES}/supine.json -o c.glb --preview nodir/p.png)
# The bad inputs of issue 8 §2 not covered above.
rise_bad_input(empty "empty.json:1:1: invalid JSON: syntax error while parsing value - unexpected end of input"
  ${bad}/empty.json -o c.glb)
rise_bad_input(not_json "not_json.json:1:1: invalid JSON: syntax error while parsing value - invalid literal"
  ${bad}/not_json.json -o c.glb)
rise_bad_input(top_type "top_array.json: found an array of 1, allowed: an object" ${bad}/top_array.json -o c.glb)
rise_bad_input(height_negative "character.height_m: found -1.7, allowed: 1.2 to 2.3 m" ${bad}/height_negative.json -o c.glb)
rise_bad_input(mass_zero "character.mass_kg: found 0, allowed: 30 to 200 kg" ${bad}/mass_zero.json -o c.glb)
rise_bad_input(nan "nan.json:1:29: invalid JSON: syntax error while parsing value - invalid literal" ${bad}/nan.json -o c.glb)
rise_bad_input(huge_number "huge_number.json:1:23: found the number 1e400, allowed: numbers a double can hold"
  ${bad}/huge_number.json -o c.glb)
rise_bad_input(angle_limit "start.joints_deg.shin_l\\[0\\]: found 200, allowed: 0 to 150 degrees \\(flexion\\)"
  ${bad}/angle_limit.json -o c.glb)
rise_bad_input(joint_unknown "start.joints_deg.tail: unknown joint \"tail\" allowed: abdomen, chest, head"
  ${bad}/joint_unknown.json -o c.glb)
rise_bad_input(self_overlap "start.joints_deg: found a pose in which the thigh_l and thigh_r boxes pass 14.4 cm into each other"
  ${bad}/self_overlap.json -o c.glb)
# Read-only means no write permission bits: refused before the simulation, even when root runs it.
rise_cli_test(bad_read_only_folder EXIT 2 REGEX "cannot write 'ro/c.glb': folder 'ro' is read-only"
  ARGS ${RISE_SAMPLES}/supine.json -o ro/c.glb ABSENT ro/c.glb ro/c.meta.json SETUP sh -c "mkdir ro && chmod a-w ro")
rise_cli_test(bad_read_only_file EXIT 2 REGEX "cannot write 'c.glb': the file is read-only"
  ARGS ${RISE_SAMPLES}/supine.json -o c.glb PRESENT c.glb ABSENT c.meta.json SETUP sh -c "echo old > c.glb && chmod a-w c.glb")
rise_cli_test(bad_output_is_input EXIT 2 REGEX "in.glb \\(its file in.meta.json\\): would overwrite the input file"
  ARGS in.meta.json -o in.glb PRESENT in.meta.json ABSENT in.glb
  SETUP ${CMAKE_COMMAND} -E copy ${RISE_SAMPLES}/supine.json in.meta.json)
# The usual naming, walk.json -o walk.glb, leaves the input alone (the sidecar is walk.meta.json).
rise_cli_test(generate_beside_input EXIT 1 REGEX "1.00 s"
  ARGS in.json -o in.glb --max-duration 1 PRESENT in.json in.glb in.meta.json
  SETUP ${CMAKE_COMMAND} -E copy ${RISE_SAMPLES}/supine.json in.json)

# --- batch manifests and options ---
set(tiny ${RISE_CLI_DIR}/tiny_library.json)
function(rise_bad_batch name regex)
  rise_cli_test(bad_batch_${name} EXIT 2 REGEX "${regex}" ARGS batch ${ARGN} ABSENT out/index.json SETUP ${CMAKE_COMMAND} -E make_directory out)
endfunction()
rise_bad_batch(unknown_key "cross.sedes: unknown key \"sedes\", did you mean \"seeds\"\\?" ${bad}/manifest_unknown_key.json -o out)
rise_bad_batch(duplicate_name "clips\\[1\\]: found the clip name \"a\" a second time" ${bad}/manifest_duplicate_name.json -o out)
rise_bad_batch(range_count "cross.bodies\\[0\\].height_m.count: found 0, allowed: a whole number from 1 to 1000"
  ${bad}/manifest_range_count.json -o out)
rise_bad_batch(format "formats\\[0\\]: found \"fbx\" \\(a string\\), allowed: glb, gltf, bvh" ${bad}/manifest_format.json -o out)
rise_bad_batch(start "cross.starts\\[1\\].posture: found \"lying\"" ${bad}/manifest_start.json -o out)
rise_bad_batch(style_name "cross.styles\\[0\\]: missing key \"name\"" ${bad}/manifest_style_name.json -o out)
rise_bad_batch(body_mismatch "clips\\[1\\]: clip \"c\" of body \"b\" has another character" ${bad}/manifest_body_mismatch.json -o out)
rise_bad_batch(shard "--shard: found \"2/2\", allowed: I/N with 0 <= I < N" ${tiny} -o out --shard 2/2)
rise_bad_batch(shard_library "--library-glb: found with --shard" ${tiny} -o out --shard 0/2 --library-glb)
rise_cli_test(bad_batch_out_folder EXIT 2 REGEX "taken: cannot make the output folder"
  ARGS batch ${tiny} -o taken SETUP ${CMAKE_COMMAND} -E touch taken)
rise_bad_batch(jobs "--jobs: Value 0 not in range" ${tiny} -o out --jobs 0)
rise_cli_test(bad_batch_read_only EXIT 2 REGEX "cannot write 'ro/index.json': folder 'ro' is read-only"
  ARGS batch ${tiny} -o ro ABSENT ro/index.json SETUP sh -c "mkdir ro && chmod a-w ro")

# A batch of clips that cannot stand in 2 s: every clip written and indexed as failed, exit 1.
rise_cli_test(batch_failures EXIT 1
  REGEX "4 clips: 0 ok, 4 failed, 0 errors, 0 pending.*back_supine_s1 failed: missed the quality bars: ends standing"
  ARGS batch ${tiny} -o out --jobs 2 --library-glb SETUP ${CMAKE_COMMAND} -E make_directory out
  PRESENT out/index.json out/back_supine_s1.glb out/back_supine_s1.bvh out/back_supine_s1.meta.json
          out/side_side_left_s1.glb out/stomach_prone_turned_s1.glb out/custom_dropped.glb
          out/library_default.glb out/library_small.glb)

foreach(mode determinism resume shards)
  add_test(NAME cli.batch_${mode} COMMAND ${CMAKE_COMMAND} -DMODE=${mode} -DRISE_GEN=$<TARGET_FILE:rise-gen>
    -DMANIFEST=${tiny} -DWORKDIR=${RISE_CLI_WORK}/batch_${mode} -P ${RISE_CLI_DIR}/batch_runs.cmake)
  set_tests_properties(cli.batch_${mode} PROPERTIES LABELS cli)
endforeach()

# --- check (0 pass, 1 fail, 2 unreadable) and preview ---
set(fixture SETUP $<TARGET_FILE:write_check_fixture> .)
rise_cli_test(check_pass EXIT 0 REGEX "PASS BVH vs glTF.*PASS overall with the BVH" ARGS check rise.glb --bvh rise.bvh ${fixture})
rise_cli_test(check_json EXIT 0 REGEX "\"passed\": true" ARGS check rise.glb --json ${fixture})
rise_cli_test(check_fail EXIT 1 REGEX "FAIL ends standing.*FAIL overall"
  ARGS check c.glb SETUP $<TARGET_FILE:rise-gen> ${RISE_SAMPLES}/supine.json -o c.glb --max-duration 1 -q)
rise_cli_test(check_bvh_mismatch EXIT 1 REGEX "FAIL BVH vs glTF: the BVH file has 31 frames, the glTF file 91"
  ARGS check rise.glb --bvh c.bvh
  SETUP sh -c "$<TARGET_FILE:write_check_fixture> . && $<TARGET_FILE:rise-gen> ${RISE_SAMPLES}/supine.json -o c.bvh --max-duration 1 -q")
rise_cli_test(check_unreadable EXIT 2 REGEX "rise-gen: error: cannot read glTF .*not_a_clip.glb" ARGS check ${bad}/not_a_clip.glb)
rise_cli_test(check_missing EXIT 2 REGEX "rise-gen: error: .*nowhere.glb" ARGS check nowhere.glb)
rise_cli_test(preview_clip EXIT 0 REGEX "rise.glb -> sheet.png" ARGS preview rise.glb -o sheet.png --frames 6 --columns 3 ${fixture}
  PRESENT sheet.png)
rise_cli_test(preview_input EXIT 0 REGEX "side.json -> sheet.png" ARGS preview ${RISE_SAMPLES}/side.json -o sheet.png --max-duration 1
  PRESENT sheet.png ABSENT sheet.json)
rise_cli_test(preview_bad EXIT 2 REGEX "nodir/sheet.png: folder 'nodir' does not exist" ARGS preview rise.glb -o nodir/sheet.png ${fixture})

# Ctrl-C mid-batch on the 40-clip sample library.
add_test(NAME cli.batch_interrupt COMMAND sh ${RISE_CLI_DIR}/interrupt.sh $<TARGET_FILE:rise-gen>
  ${RISE_SAMPLES}/library.json ${RISE_CLI_WORK}/batch_interrupt ${CMAKE_COMMAND})
set_tests_properties(cli.batch_interrupt PROPERTIES PASS_REGULAR_EXPRESSION "index valid: [0-9]+ finished, [0-9]+ pending"
  FAIL_REGULAR_EXPRESSION "RISE_INTERRUPT_FAILED" LABELS cli)

# SIGKILL mid-write, one clip and a batch: every output stays the complete old or new file.
add_executable(kill_mid_write ${RISE_CLI_DIR}/kill_mid_write.cpp)
target_link_libraries(kill_mid_write PRIVATE rise_export nlohmann_json::nlohmann_json rise_options)
add_test(NAME cli.kill_mid_write COMMAND kill_mid_write $<TARGET_FILE:rise-gen> ${RISE_SAMPLES}/supine.json ${tiny}
  ${RISE_CLI_WORK}/kill_mid_write)
set_tests_properties(cli.kill_mid_write PROPERTIES PASS_REGULAR_EXPRESSION "never lose work: every check held"
  FAIL_REGULAR_EXPRESSION "RISE_KILL_FAILED" LABELS cli)
