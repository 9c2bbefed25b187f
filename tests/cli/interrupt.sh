#!/bin/sh
# SPDX-License-Identifier: MIT
# Ctrl-C during a batch: rise-gen finishes the clips in flight, exits 1 with a resume hint, and
# leaves index.json valid with the unfinished clips "pending" and every finished clip's files.
# Usage: interrupt.sh <rise-gen> <manifest> <work folder> <cmake>
set -u
rise_gen=$1 manifest=$2 work=$3 cmake=$4
rm -rf "$work" && mkdir -p "$work/out" || exit 1
"$rise_gen" batch "$manifest" -o "$work/out" --jobs 2 2> "$work/stderr" > /dev/null &
pid=$!
# Wait for the first finished clip, so the interrupt lands mid-run.
for i in $(seq 1 200); do
  ls "$work/out"/*.glb > /dev/null 2>&1 && break
  sleep 0.05
done
kill -INT "$pid"
wait "$pid"
code=$?
cat "$work/stderr"
[ "$code" -eq 1 ] || { echo "RISE_INTERRUPT_FAILED: exit code $code, expected 1"; exit 1; }
grep -q "stopped by Ctrl-C; run the same command again to resume" "$work/stderr" ||
  { echo "RISE_INTERRUPT_FAILED: no resume hint"; exit 1; }
cat > "$work/check.cmake" <<CHECK
cmake_minimum_required(VERSION 3.25)
file(READ "$work/out/index.json" index)
string(JSON pending GET "\${index}" summary pending)
string(JSON clips LENGTH "\${index}" clips)
math(EXPR last "\${clips} - 1")
set(finished 0)
foreach(i RANGE \${last})
  string(JSON status GET "\${index}" clips \${i} status)
  string(JSON glb GET "\${index}" clips \${i} files glb)
  if(status STREQUAL "pending")
    if(EXISTS "$work/out/\${glb}")
      message(FATAL_ERROR "pending clip \${glb} has a file")
    endif()
  else()
    math(EXPR finished "\${finished} + 1")
    if(NOT EXISTS "$work/out/\${glb}")
      message(FATAL_ERROR "finished clip \${glb} has no file")
    endif()
  endif()
endforeach()
if(pending EQUAL 0 OR finished EQUAL 0)
  message(FATAL_ERROR "expected both finished and pending clips: \${finished} finished, \${pending} pending")
endif()
message("index valid: \${finished} finished, \${pending} pending")
CHECK
"$cmake" -P "$work/check.cmake" || { echo "RISE_INTERRUPT_FAILED: index check"; exit 1; }
