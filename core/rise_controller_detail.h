// SPDX-License-Identifier: MIT
// What the rise controller's files share (core/rise_*.cpp, one per stage of the
// get-up): the tuning constants more than one stage reads, and small geometry
// helpers. Private to those files.
#pragma once

#include "core/bezier.h"
#include "core/biped.h"
#include "core/rise_controller.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtx/matrix_operation.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace rise::rise_controller_detail {

inline constexpr float kPi = glm::pi<float>();
inline const glm::vec3 kUp(0.0f, 1.0f, 0.0f);

// Tracking-error gate: moves slow down when the pelvis lags its goal.
inline constexpr float kGateError = 0.06f;  // m: full speed below this
inline constexpr float kGateStop = 0.20f;   // m: slowest pace at and above this
inline constexpr double kStallTime = 1.5;   // s a move may lag beyond kGateStop before it is re-planned

// Lengths marked "m, Scaled" are a kTunedHeight body's; a shorter body's are
// shorter by its height's share (RiseController::Scaled).

inline constexpr float kReachTolerance = 0.01f;   // m a planned limb may miss its place by
inline constexpr float kLandedClearance = 0.02f;  // m above the ground a placed hand or foot counts as down

// Phase 2 starts once the CoM's ground projection is this far inside the feet.
inline constexpr float kRiseMargin = 0.02f;  // m, Scaled
// ... or, from a heels-down with the soles flat, once it is within this of them.
inline constexpr float kHeelsDownReach = 0.02f;  // m, Scaled

// Feet this far either side of the hands' midline in the crawl: narrow, so
// the knees come in between the arms as the feet walk up to the hands and the
// squat the rise starts from is balanced side to side (0.10-0.15 m measured:
// 11, 14 and 5 of 36 prone starts stood).
inline constexpr float kCrawlHalfStance = 0.12f;  // m, Scaled

// CoM feedback on hands and feet: proportional gain, integral gain (1/s), integral bound.
inline constexpr float kCrawlComGain = 0.5f;
inline constexpr float kCrawlComIntegral = 1.0f;
inline constexpr float kMaxCrawlOffset = 0.06f;  // m, Scaled

// Phase 2's balance in the pose: how far the pelvis may slide and the trunk lean.
inline constexpr float kMaxBalanceSlide = 0.1f;  // m, Scaled: how far the pelvis may slide from its planned place
inline constexpr float kMaxBalanceLean = 1.2f;   // rad the trunk may lean forward of its plan
inline constexpr float kLeanRate = 0.8f;         // rad/s the balance lean may change
inline constexpr float kLeanTolerance = 0.002f;  // rad: the balance lean's search stops this close

// The feet walk in while the hands are farther than this ahead of them (from
// nearer, a foot can hardly come further under a body bent at the hips); a
// foot step is at most kFootStep long. The hips rise from the bear stance into
// a pike as the hands come from kPikeStart to kFootWalkDistance ahead.
inline constexpr float kFootWalkDistance = 0.5f;  // m at kTunedHeight
inline constexpr float kPikeStart = 1.1f;         // m at kTunedHeight
inline constexpr float kPikeComRatio = 0.62f;     // CoM height of the pike as the feet come in, of standing
inline constexpr float kFootStep = 0.3f;          // m at kTunedHeight
inline constexpr float kFootLead = 0.1f;          // m, Scaled
inline constexpr float kMinFootStep = 0.06f;      // m, Scaled: a reachable step shorter than this ends the walk-in

// The sit back puts the CoM this far behind the middle of the flat soles: far
// enough in that the rise starts with room to brake a drift either way. A
// shorter body (shorter feet) aims nearer by its height's share: unscaled, the
// aim of a 1.45 m body was 1 cm inside its heels. Stress seeds 5001-6000 and
// 9001-9500: 961 -> 965 of 1500 stood (24 runs changed, 14 won, 10 lost).
inline constexpr float kSitBackBehindSoles = 0.1f;  // m, Scaled

// The roll (RiseController::RollAngle: 0 on the back, pi on the front): the far
// foot pushes until the pelvis has turned this far, or has pushed off once
// the pelvis is past kLiftOffRoll; the chest past kChestOverRoll has led over
// and the legs straighten; both past kProneRoll lie prone.
inline constexpr float kLiftOffRoll = glm::radians(30.0f);
inline constexpr float kPushedRoll = glm::radians(60.0f);

// On hands and feet: where the plan is quasi-static and the CoM is held by feedback.
inline bool OnHandsAndFeet(RisePhase phase) {
  return phase == RisePhase::kPush || phase == RisePhase::kCrawl;
}

inline glm::vec3 Horizontal(const glm::vec3& v) {
  return {v.x, 0.0f, v.z};
}

inline glm::vec3 SafeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
  const float length = glm::length(v);
  return length > 1e-5f ? v / length : fallback;
}

inline float Height(const physics::PlaneShape& plane, const glm::vec3& p) {
  return glm::dot(plane.normal, p) - plane.offset;
}
inline glm::vec3 Project(const physics::PlaneShape& plane, const glm::vec3& p) {
  return p - plane.normal * Height(plane, p);
}
// A vector's part along the plane (its normal part taken out).
inline glm::vec3 AlongPlane(const physics::PlaneShape& plane, const glm::vec3& v) {
  return v - plane.normal * glm::dot(v, plane.normal);
}

}  // namespace rise::rise_controller_detail
