# SPDX-License-Identifier: MIT
# Batch properties that need several runs of rise-gen batch on the tiny manifest:
#   -DMODE=determinism  --jobs 1 and --jobs 2 give byte-identical folders (clips, sidecars,
#                       previews, library files, index.json)
#   -DMODE=resume       a second run skips every clip and leaves every file byte-identical
#   -DMODE=shards       shards 0/2 and 1/2 into one folder give the full run's files; the same
#                       command without --shard then finds all up to date and writes the same
#                       index.json and library files as the full run
#   -DRISE_GEN=path -DMANIFEST=path -DWORKDIR=dir
# The folders do not exist before their first run: rise-gen batch makes them.
file(REMOVE_RECURSE ${WORKDIR})

function(batch dir)
  execute_process(COMMAND ${RISE_GEN} batch ${MANIFEST} -o ${dir} --previews ${ARGN}
    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("batch ${ARGN}: exit ${code}: ${out}")
  # The tiny clips are too short to stand, so every run ends with exit code 1.
  if(NOT code EQUAL 1)
    message(FATAL_ERROR "exit code ${code}, expected 1: ${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

# Fails unless folders a and b hold the same file names (`ignore` regex left out) with the same bytes.
function(compare_folders a b ignore)
  file(GLOB files_a RELATIVE ${a} ${a}/*)
  file(GLOB files_b RELATIVE ${b} ${b}/*)
  list(FILTER files_a EXCLUDE REGEX "${ignore}")
  list(FILTER files_b EXCLUDE REGEX "${ignore}")
  list(SORT files_a)
  list(SORT files_b)
  if(NOT files_a STREQUAL files_b)
    message(FATAL_ERROR "different files:\n${files_a}\n${files_b}")
  endif()
  list(LENGTH files_a count)
  if(count LESS 10)
    message(FATAL_ERROR "only ${count} files: ${files_a}")
  endif()
  foreach(f ${files_a})
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${a}/${f} ${b}/${f} RESULT_VARIABLE differ)
    if(differ)
      message(FATAL_ERROR "${f} differs between ${a} and ${b}")
    endif()
  endforeach()
  message("${count} files identical")
endfunction()

batch(${WORKDIR}/full --jobs 1 --library-glb)
if(MODE STREQUAL "determinism")
  batch(${WORKDIR}/other --jobs 2 --library-glb)
  compare_folders(${WORKDIR}/full ${WORKDIR}/other "^$")
elseif(MODE STREQUAL "resume")
  file(COPY ${WORKDIR}/full/ DESTINATION ${WORKDIR}/other)
  file(TIMESTAMP ${WORKDIR}/other/back_supine_s1.glb before "%s")
  execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1.1)
  batch(${WORKDIR}/other --jobs 2 --library-glb)
  if(NOT last_output MATCHES "\\(4 up to date, skipped\\)")
    message(FATAL_ERROR "the rerun did not skip all 4 clips")
  endif()
  file(TIMESTAMP ${WORKDIR}/other/back_supine_s1.glb after "%s")
  if(NOT before STREQUAL after)
    message(FATAL_ERROR "a skipped clip was rewritten")
  endif()
  compare_folders(${WORKDIR}/full ${WORKDIR}/other "^$")
elseif(MODE STREQUAL "shards")
  batch(${WORKDIR}/other --jobs 1 --shard 0/2)
  batch(${WORKDIR}/other --jobs 1 --shard 1/2)
  if(NOT EXISTS ${WORKDIR}/other/index-0-of-2.json OR NOT EXISTS ${WORKDIR}/other/index-1-of-2.json)
    message(FATAL_ERROR "a shard index is missing")
  endif()
  compare_folders(${WORKDIR}/full ${WORKDIR}/other "^(index.*|library_.*)$")
  batch(${WORKDIR}/other --jobs 2 --library-glb)
  if(NOT last_output MATCHES "\\(4 up to date, skipped\\)")
    message(FATAL_ERROR "the run after the shards did not find all 4 clips")
  endif()
  compare_folders(${WORKDIR}/full ${WORKDIR}/other "^index-")
else()
  message(FATAL_ERROR "unknown MODE ${MODE}")
endif()
