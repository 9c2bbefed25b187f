// SPDX-License-Identifier: MIT
// RiseSpec: everything one clip is generated from, as read from the input JSON
// (see schema/rise-input.schema.json for the file format, units and ranges).
//
// Every field holds its default after default construction, so RiseSpec{} is
// the spec of an input file "{}". Numbers are doubles so a spec survives the
// round trip through JSON text (RiseSpecToJson) bit for bit.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/biped_def.h"

namespace rise {

enum class Posture { kSupine, kProne, kSideLeft, kSideRight, kCustom };

// JSON spelling of a posture ("supine", "prone", "side_left", "side_right", "custom").
const char* PostureName(Posture posture);

struct CharacterSpec {
  double heightM = 1.75;      // [1.2, 2.3]
  double massKg = 70.0;       // [30, 200]
  SegmentOverrides segments;  // per-segment size/mass overrides, keyed by SegmentNames()
};

// The lying pose the clip starts from. The root orientation of a posture is
// rotated by headingDeg about +Y and then tilted onto the slope; the body is
// placed so its lowest point is just above the ground.
//   supine     lying on the back, face up, head toward -Z at heading 0
//   prone      lying on the front, face down, head toward +Z
//   side_left  lying on the left side, head toward +X
//   side_right lying on the right side, head toward -X
//   custom     rootEulerDeg gives the pelvis orientation
struct StartSpec {
  Posture posture = Posture::kSupine;
  double headingDeg = 0.0;  // [-360, 360], rotation about +Y
  // custom only: pelvis rotation as intrinsic X, then Y, then Z rotations (degrees).
  std::array<double, 3> rootEulerDeg{0.0, 0.0, 0.0};
  // Joint angles in degrees by joint (bone) name, DOFs as in biped_def.h. They
  // replace the posture's own angles for the joints listed.
  std::map<std::string, std::vector<double>> jointsDeg;
  double dropHeightM = 0.0;  // [0, 2]; > 0 drops the body as a ragdoll from this height first
};

// The ground is a plane through the origin rising toward +Z by slopeDeg.
struct TerrainSpec {
  double slopeDeg = 0.0;  // [0, 30]
  double friction = 0.8;  // [0.05, 2], Coulomb coefficient
};

struct StyleSpec {
  double speed = 1.0;         // [0.25, 3], pace multiplier of the rise
  double stepHeightM = 0.08;  // [0.02, 0.3], how high a hand or foot lifts when it moves
  double stanceWidthM = 0.3;  // [0.1, 0.6], distance between the feet when standing
  double sway = 0.0;          // [0, 1], secondary swaying motion (priority layer)
  double tiredness = 0.0;     // [0, 1], slows every move (StylePace)
  double lookAround = 0.0;    // [0, 1], head turns during the rise (priority layer)
};

// An external push, for testing the feedback: force on one body's centre.
struct Disturbance {
  double timeS = 0.0;                           // [0, maxDurationS], start time
  std::string body;                             // a joint name from SegmentNames()
  std::array<double, 3> forceN{0.0, 0.0, 0.0};  // world, each component in [-5000, 5000]
  double durationS = 0.0;                       // (0, 5]
};

// Output choices the CLI may override.
struct OutputSpec {
  std::string names = "default";  // joint naming preset: "default", "mixamo", "ue"
  bool rootMotion = true;         // false: in-place clip (root translation removed in the plane)
};

struct RiseSpec {
  CharacterSpec character;
  StartSpec start;
  TerrainSpec terrain;
  StyleSpec style;
  std::vector<Disturbance> disturbances;
  uint64_t seed = 1;           // [0, 2^53]
  double fps = 30.0;           // [1, 240]
  double maxDurationS = 60.0;  // [1, 120]; when the input leaves it out, DefaultMaxDurationS (supine: 60)
  bool maxDurationGiven = false;  // set by the input (or an override), not DefaultMaxDurationS
  OutputSpec output;
};

// How fast the style moves, 1 the default: speed (at least 0.25) x (1 - 0.4 tiredness).
double StylePace(const StyleSpec& style);

// max_duration_s when the input leaves it out: 35 s lying prone, 60 s from any
// other start (the roll), divided by the style's pace (speed x (1 - 0.4
// tiredness)) when that is below 1; at most 120 s.
double DefaultMaxDurationS(const RiseSpec& spec);

// The body the spec describes.
BipedDef MakeBipedDef(const CharacterSpec& character);

}  // namespace rise
