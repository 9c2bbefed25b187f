# SPDX-License-Identifier: MIT
# Imports the sample .glb and .bvh files into real Blender (headless) and checks
# what an artist would see: the import reports no error, the armature has the
# expected bones, the action spans the clip's frames, and the head bone's world
# position at the last frame is within 2 cm of rise-gen's.
#
# Run: blender -b --factory-startup --python-exit-code 1 --python blender_import.py -- <samples folder>
# (the folder that write_sample_clips filled; see tests/export/tests.cmake).
#
# Debian 12's Blender 3.4 needs two shims on Python 3.11 / numpy 1.24: its glTF
# importer still uses numpy.bool (removed in numpy 1.24) and its BVH importer
# opens files with mode "rU" (removed in Python 3.11).
import builtins
import json
import os
import sys

import warnings

import numpy

with warnings.catch_warnings():
    # numpy 1.24 warns when the removed alias is merely looked up.
    warnings.simplefilter("ignore", FutureWarning)
    if not hasattr(numpy, "bool"):
        numpy.bool = bool

_open = builtins.open


def _open_without_u(file, mode="r", *args, **kwargs):
    return _open(file, mode.replace("U", ""), *args, **kwargs)


builtins.open = _open_without_u

import bpy  # noqa: E402  (after the shims on purpose)
from mathutils import Vector  # noqa: E402

kTolerance = 0.02  # metres


def fail(message):
    print("blender_import: FAIL: " + message)
    sys.exit(1)


def reset_scene(fps):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    # The glTF importer puts keys on scene frames at scene.render.fps: set it first.
    bpy.context.scene.render.fps = int(round(fps))
    bpy.context.scene.render.fps_base = 1.0


def only_armature():
    armatures = [o for o in bpy.context.scene.objects if o.type == "ARMATURE"]
    if len(armatures) != 1:
        fail("expected one armature, found %d" % len(armatures))
    return armatures[0]


def check(label, armature, expected_bones, expected, to_blender):
    bones = sorted(b.name for b in armature.data.bones)
    if bones != sorted(expected_bones):
        fail("%s: bones %s, expected %s" % (label, bones, sorted(expected_bones)))
    action = armature.animation_data.action if armature.animation_data else None
    if action is None:
        fail("%s: no action on the armature" % label)
    first, last = (int(round(f)) for f in action.frame_range)
    frames = last - first + 1
    if frames != expected["frameCount"]:
        fail("%s: action spans frames %d..%d (%d), expected %d frames" % (label, first, last, frames, expected["frameCount"]))
    bpy.context.scene.frame_set(last)
    head = armature.matrix_world @ armature.pose.bones["head"].head
    want = to_blender(expected["headAtLastFrame"])
    error = (head - want).length
    print("blender_import: %s: %d bones, frames %d..%d, head at last frame %s vs %s (%.4f m)"
          % (label, len(bones), first, last, tuple(round(v, 4) for v in head), tuple(round(v, 4) for v in want), error))
    if error > kTolerance:
        fail("%s: head is %.4f m from rise-gen's position" % (label, error))


def y_up_to_blender(p):
    # Both importers turn Y-up files into Blender's Z-up: (x, y, z) -> (x, -z, y).
    return Vector((p[0], -p[2], p[1]))


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(argv) != 1:
        fail("usage: blender ... --python blender_import.py -- <samples folder>")
    folder = argv[0]
    with _open(os.path.join(folder, "sample_expect.json")) as f:
        expected = json.load(f)
    joints = expected["joints"]
    # BVH End Sites are bone tails, not bones.
    bvh_bones = [j for j in joints if not j.endswith("_end")]

    reset_scene(expected["fps"])
    result = bpy.ops.import_scene.gltf(filepath=os.path.join(folder, "sample.glb"))
    if result != {"FINISHED"}:
        fail("glTF import returned %s" % result)
    check("sample.glb", only_armature(), joints, expected, y_up_to_blender)
    # Blender's own re-export, read back by rise-gen's reader in the next CTest
    # (export.read_blender_glb): another tool's bone rest rotations and bind matrices.
    result = bpy.ops.export_scene.gltf(filepath=os.path.join(folder, "blender_roundtrip.glb"), export_format="GLB")
    if result != {"FINISHED"}:
        fail("glTF export returned %s" % result)

    # Extracted root motion: a ground-level "root" bone above the pelvis, same world motion.
    reset_scene(expected["fps"])
    result = bpy.ops.import_scene.gltf(filepath=os.path.join(folder, "sample_extract.glb"))
    if result != {"FINISHED"}:
        fail("glTF import of sample_extract.glb returned %s" % result)
    check("sample_extract.glb", only_armature(), ["root"] + joints, expected, y_up_to_blender)

    for name, scale, up, forward in (("sample.bvh", 1.0, "Y", "-Z"), ("sample_cm_z.bvh", 0.01, "Z", "Y")):
        reset_scene(expected["fps"])
        result = bpy.ops.import_anim.bvh(filepath=os.path.join(folder, name), global_scale=scale, axis_up=up,
                                         axis_forward=forward, update_scene_fps=True, update_scene_duration=True)
        if result != {"FINISHED"}:
            fail("BVH import of %s returned %s" % (name, result))
        check(name, only_armature(), bvh_bones, expected, y_up_to_blender)
    print("blender_import: OK")


main()
