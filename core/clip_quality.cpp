// SPDX-License-Identifier: MIT
// Measures a clip against the quality bars (see clip_quality.h for the rules).
#include "core/clip_quality.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <limits>

#include "base/assert.h"

namespace rise {
namespace {

constexpr const char* kEffectors[] = {"hand_l", "hand_r", "foot_l", "foot_r"};

// One point the bars follow on the body: a corner of a joint's box, or the
// joint itself (corner < 0) when the skeleton carries no boxes.
struct BodyPoint {
  int joint = 0;
  int corner = -1;
};

struct Pose {
  std::vector<glm::vec3> positions;
  std::vector<glm::quat> rotations;
};

struct Ground {
  glm::vec3 point;
  glm::vec3 normal;  // unit

  float Height(const glm::vec3& p) const { return glm::dot(p - point, normal); }
  glm::vec3 AlongPlane(const glm::vec3& d) const { return d - glm::dot(d, normal) * normal; }
};

glm::vec3 PointAt(const Skeleton& skeleton, const Pose& pose, BodyPoint point) {
  if (point.corner < 0) return pose.positions[point.joint];
  return pose.positions[point.joint] + pose.rotations[point.joint] * skeleton.joints[point.joint].box.Corner(point.corner);
}

// The points of the given joints: their box corners, or the joints themselves
// for a skeleton without boxes.
std::vector<BodyPoint> PointsOf(const Skeleton& skeleton, const std::vector<int>& joints, bool useBoxes) {
  std::vector<BodyPoint> points;
  for (int joint : joints) {
    if (!useBoxes) {
      points.push_back({joint, -1});
    } else if (skeleton.joints[joint].hasBox) {
      for (int corner = 0; corner < 8; ++corner) points.push_back({joint, corner});
    }
  }
  return points;
}

// A joint and all its descendants (parents precede children, so one pass finds them).
std::vector<int> Subtree(const Skeleton& skeleton, int root) {
  std::vector<int> joints{root};
  std::vector<bool> inside(skeleton.joints.size(), false);
  inside[root] = true;
  for (int j = root + 1; j < skeleton.JointCount(); ++j) {
    const int parent = skeleton.joints[j].parent;
    if (parent >= 0 && inside[parent]) {
      inside[j] = true;
      joints.push_back(j);
    }
  }
  return joints;
}

// Index into `points` of the lowest one.
size_t Lowest(const Skeleton& skeleton, const Pose& pose, const Ground& ground, const std::vector<BodyPoint>& points) {
  size_t best = 0;
  float bestHeight = std::numeric_limits<float>::max();
  for (size_t i = 0; i < points.size(); ++i) {
    const float h = ground.Height(PointAt(skeleton, pose, points[i]));
    if (h < bestHeight) {
      bestHeight = h;
      best = i;
    }
  }
  return best;
}

double DegreesBetween(const glm::vec3& a, const glm::vec3& b) {
  const float lengths = glm::length(a) * glm::length(b);
  if (!(lengths > 0.0f)) return 90.0;
  return glm::degrees(std::acos(std::clamp(glm::dot(a, b) / lengths, -1.0f, 1.0f)));
}

std::string Format(const char* format, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
  char text[160];
  std::snprintf(text, sizeof text, format, a, b, c, d);
  return text;
}

const char* Verdict(bool ok) {
  return ok ? "PASS" : "FAIL";
}

// Figures in JSON to a micrometre (or micro-degree, microsecond): enough for
// every bar, and the index reads without float noise.
double Rounded(double value) {
  return std::round(value * 1e6) / 1e6;
}

}  // namespace

QualityReport MeasureClip(const Clip& clip, const QualityOptions& options) {
  QualityReport report;
  if (std::string problem = clip.Validate(); !problem.empty()) {
    report.error = "invalid clip: " + problem;
    return report;
  }
  const Skeleton& skeleton = clip.skeleton;
  for (const char* name : {"pelvis", "head", "hand_l", "hand_r", "foot_l", "foot_r"}) {
    if (skeleton.Find(name) < 0) {
      report.error = std::string("clip has no joint named '") + name + "'";
      return report;
    }
  }
  const float normalLength = glm::length(options.groundNormal);
  RISE_ASSERT_MSG(normalLength > 0.0f, "ground normal must not be zero");
  const Ground ground{options.groundPoint, options.groundNormal / normalLength};

  const int pelvis = skeleton.Find("pelvis");
  const int head = skeleton.Find("head");
  const int trunkTop = skeleton.Find("chest") >= 0 ? skeleton.Find("chest") : head;
  const bool useBoxes = std::any_of(skeleton.joints.begin(), skeleton.joints.end(),
                                    [](const SkeletonJoint& joint) { return joint.hasBox; });
  std::vector<std::vector<BodyPoint>> effectorPoints;
  for (const char* name : kEffectors) {
    effectorPoints.push_back(PointsOf(skeleton, Subtree(skeleton, skeleton.Find(name)), useBoxes));
    if (effectorPoints.back().empty()) {
      report.error = std::string("'") + name + "' and its children carry no box";
      return report;
    }
  }
  std::vector<int> allJoints(skeleton.joints.size());
  for (int j = 0; j < skeleton.JointCount(); ++j) allJoints[j] = j;
  const std::vector<BodyPoint> bodyPoints = PointsOf(skeleton, allJoints, useBoxes);

  const int frames = clip.FrameCount();
  std::vector<Pose> poses(frames);
  for (int f = 0; f < frames; ++f) poses[f] = {clip.WorldPositions(f), clip.WorldRotations(f)};

  report.frames = frames;
  report.fps = clip.fps;
  report.duration = clip.Duration();

  // Standing height: head above the soles in the bind pose, so a rig whose
  // bind pose does not stand on y = 0 measures the same.
  Pose bind{skeleton.BindPositions(), std::vector<glm::quat>(skeleton.joints.size(), glm::quat(1, 0, 0, 0))};
  const Ground flat{glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f)};
  float soles = std::numeric_limits<float>::max();
  for (int e = 2; e < 4; ++e) {
    const auto& points = effectorPoints[e];
    soles = std::min(soles, flat.Height(PointAt(skeleton, bind, points[Lowest(skeleton, bind, flat, points)])));
  }
  report.standingHeadHeight = bind.positions[head].y - soles;
  if (!(report.standingHeadHeight > 0.0)) {
    report.error = "the bind pose does not stand: its head is not above its feet";
    return report;
  }

  auto headRatio = [&](const Pose& pose) { return ground.Height(pose.positions[head]) / report.standingHeadHeight; };
  auto tilt = [&](const Pose& pose) {
    return DegreesBetween(pose.positions[head] - pose.positions[pelvis], glm::vec3(0.0f, 1.0f, 0.0f));
  };
  auto footHeight = [&](const Pose& pose, int effector) {
    const auto& points = effectorPoints[effector];
    return double(ground.Height(PointAt(skeleton, pose, points[Lowest(skeleton, pose, ground, points)])));
  };
  auto standing = [&](const Pose& pose) {
    return headRatio(pose) >= options.standHeadRatio && tilt(pose) <= options.standTiltDeg &&
           std::fabs(footHeight(pose, 2)) <= options.standFootHeight &&
           std::fabs(footHeight(pose, 3)) <= options.standFootHeight;
  };

  // Start.
  const Pose& first = poses.front();
  report.startHeadRatio = headRatio(first);
  report.startTrunkDeg = 90.0 - DegreesBetween(first.positions[trunkTop] - first.positions[pelvis], ground.normal);
  report.startTrunkDeg = std::fabs(report.startTrunkDeg);
  report.startsLying = report.startHeadRatio < options.lyingHeadRatio && report.startTrunkDeg <= options.lyingTrunkDeg;

  // End.
  const Pose& last = poses.back();
  report.headHeightRatio = headRatio(last);
  report.trunkTiltEnd = tilt(last);
  report.footHeightEndL = footHeight(last, 2);
  report.footHeightEndR = footHeight(last, 3);
  int standFrom = frames;
  while (standFrom > 0 && standing(poses[standFrom - 1])) --standFrom;
  if (standFrom < frames) report.timeToStand = standFrom / clip.fps;
  report.endsStanding = report.timeToStand >= 0.0 && report.duration - report.timeToStand >= options.standWindow - 1e-9;

  // Ground penetration.
  float lowest = 0.0f;
  for (int f = 0; f < frames; ++f) {
    for (const BodyPoint& point : bodyPoints) {
      const float h = ground.Height(PointAt(skeleton, poses[f], point));
      if (h < lowest) {
        lowest = h;
        report.penetrationJoint = skeleton.joints[point.joint].name;
        report.penetrationFrame = f;
      }
    }
  }
  report.maxPenetration = -lowest;
  report.penetrationOk = report.maxPenetration <= options.maxPenetration;

  // Contact slip, following the touching material point (see the header).
  for (size_t e = 0; e < effectorPoints.size(); ++e) {
    const auto& points = effectorPoints[e];
    EffectorSlip slip;
    slip.effector = kEffectors[e];
    bool touching = false;
    size_t planted = 0;  // the point that touched on the previous frame
    glm::vec3 drift(0.0f);
    double contactSlip = 0.0, contactStart = 0.0;
    auto closeContact = [&](double end) {
      if (contactSlip >= options.maxSlip) slip.overBar.push_back({contactStart, end, contactSlip});
      if (slip.contactStart < 0.0 || contactSlip > slip.slip) {
        slip.slip = contactSlip;
        slip.contactStart = contactStart;
        slip.contactEnd = end;
      }
    };
    for (int f = 0; f < frames; ++f) {
      const size_t low = Lowest(skeleton, poses[f], ground, points);
      const bool touchingNow = ground.Height(PointAt(skeleton, poses[f], points[low])) <= options.contactHeight;
      if (touchingNow && touching) {
        drift += ground.AlongPlane(PointAt(skeleton, poses[f], points[planted]) -
                                   PointAt(skeleton, poses[f - 1], points[planted]));
        contactSlip = std::max(contactSlip, double(glm::length(drift)));
      } else if (touchingNow) {
        ++slip.contacts;
        drift = glm::vec3(0.0f);
        contactSlip = 0.0;
        contactStart = f / clip.fps;
      } else if (touching) {
        closeContact((f - 1) / clip.fps);
      }
      touching = touchingNow;
      planted = low;
    }
    if (touching) closeContact(report.duration);
    if (slip.slip >= report.maxSlip) {
      report.maxSlip = slip.slip;
      report.maxSlipEffector = slip.effector;
    }
    report.slips.push_back(slip);
  }
  report.slipOk = report.maxSlip < options.maxSlip;

  // Teleports: the frame time is the same everywhere, so the longest jump is the worst.
  const double frameTime = 1.0 / clip.fps;
  for (int f = 1; f < frames; ++f) {
    for (int j = 0; j < skeleton.JointCount(); ++j) {
      const double jump = glm::length(poses[f].positions[j] - poses[f - 1].positions[j]);
      if (jump > report.maxJointJumpMeters) {
        report.maxJointJumpMeters = jump;
        report.maxJointJump = jump / frameTime;
        report.jumpJoint = skeleton.joints[j].name;
        report.jumpFrame = f;
      }
    }
  }
  report.jumpOk = report.maxJointJumpMeters <= options.maxJointSpeed * frameTime + options.jumpSlack;

  report.passed = report.startsLying && report.endsStanding && report.penetrationOk && report.slipOk && report.jumpOk;
  return report;
}

nlohmann::json QualityReport::ToJson() const {
  nlohmann::json json;
  json["passed"] = passed;
  if (!error.empty()) {
    json["error"] = error;
    return json;
  }
  json["duration"] = Rounded(duration);
  json["frames"] = frames;
  json["fps"] = fps;
  json["standing_head_height"] = Rounded(standingHeadHeight);
  json["starts_lying"] = {
      {"passed", startsLying}, {"head_ratio", Rounded(startHeadRatio)}, {"trunk_deg", Rounded(startTrunkDeg)}};
  json["ends_standing"] = {
      {"passed", endsStanding},
      {"time_to_stand", timeToStand >= 0.0 ? nlohmann::json(Rounded(timeToStand)) : nlohmann::json()},
      {"head_ratio", Rounded(headHeightRatio)},
      {"trunk_tilt_deg", Rounded(trunkTiltEnd)},
      {"foot_height_l", Rounded(footHeightEndL)},
      {"foot_height_r", Rounded(footHeightEndR)}};
  json["penetration"] = {{"passed", penetrationOk},
                         {"max", Rounded(maxPenetration)},
                         {"joint", penetrationJoint},
                         {"frame", penetrationFrame}};
  nlohmann::json effectors = nlohmann::json::object();
  for (const EffectorSlip& slip : slips) {
    effectors[slip.effector] = {{"slip", Rounded(slip.slip)}, {"contacts", slip.contacts}};
    if (slip.contacts > 0) {
      effectors[slip.effector]["worst_contact"] = {Rounded(slip.contactStart), Rounded(slip.contactEnd)};
    }
    nlohmann::json overBar = nlohmann::json::array();
    for (const ContactSlide& contact : slip.overBar) {
      overBar.push_back({{"start", Rounded(contact.start)}, {"end", Rounded(contact.end)}, {"slip", Rounded(contact.slip)}});
    }
    effectors[slip.effector]["over_bar"] = overBar;
  }
  json["slip"] = {
      {"passed", slipOk}, {"max", Rounded(maxSlip)}, {"effector", maxSlipEffector}, {"effectors", effectors}};
  json["joint_jump"] = {{"passed", jumpOk},
                        {"max_speed", Rounded(maxJointJump)},
                        {"max_distance", Rounded(maxJointJumpMeters)},
                        {"joint", jumpJoint},
                        {"frame", jumpFrame}};
  return json;
}

std::string QualityReport::Summary() const {
  if (!error.empty()) return "FAIL cannot measure the clip: " + error + "\n";
  std::string text = Format("clip: %.2f s, %.0f frames at %g fps\n", duration, frames, fps);
  text += std::string(Verdict(startsLying)) +
          Format(" starts lying    head at %.0f%% of standing height, trunk %.1f deg from the ground\n",
                 100.0 * startHeadRatio, startTrunkDeg);
  text += std::string(Verdict(endsStanding)) + " ends standing   " +
          (timeToStand >= 0.0 ? Format("stands from %.2f s", timeToStand) : std::string("never stands")) +
          Format("; at the end head %.0f%%, tilt %.1f deg, feet %.3f / %.3f m\n", 100.0 * headHeightRatio, trunkTiltEnd,
                 footHeightEndL, footHeightEndR);
  text += std::string(Verdict(penetrationOk)) + Format(" ground          deepest %.3f m below", maxPenetration) +
          (penetrationFrame >= 0 ? " (" + penetrationJoint + Format(", frame %.0f)", penetrationFrame) : "") + "\n";
  text += std::string(Verdict(slipOk)) + Format(" contact slip    worst %.3f m", maxSlip);
  for (const EffectorSlip& slip : slips) {
    if (slip.effector == maxSlipEffector && slip.contacts > 0) {
      text += " (" + slip.effector + Format(", contact %.2f-%.2f s)", slip.contactStart, slip.contactEnd);
    }
  }
  text += "\n";
  text += std::string(Verdict(jumpOk)) + Format(" no teleport     fastest joint %.1f m/s", maxJointJump) +
          (jumpFrame >= 0 ? " (" + jumpJoint + Format(", frame %.0f)", jumpFrame) : "") + "\n";
  text += std::string(Verdict(passed)) + " overall\n";
  return text;
}

std::vector<std::vector<glm::vec3>> JointPositionSequence(const Clip& clip) {
  std::vector<std::vector<glm::vec3>> sequence;
  sequence.reserve(clip.FrameCount());
  for (int f = 0; f < clip.FrameCount(); ++f) sequence.push_back(clip.WorldPositions(f));
  return sequence;
}

FastestBox MeasureFastestBox(const Clip& clip) {
  FastestBox fastest;
  std::vector<glm::vec3> previous;
  for (int f = 0; f < clip.FrameCount(); ++f) {
    const std::vector<glm::vec3> positions = clip.WorldPositions(f);
    const std::vector<glm::quat> rotations = clip.WorldRotations(f);
    std::vector<glm::vec3> centres(positions.size());
    for (size_t j = 0; j < centres.size(); ++j) {
      centres[j] = positions[j] + rotations[j] * clip.skeleton.joints[j].box.center;
      if (f == 0 || !clip.skeleton.joints[j].hasBox) continue;
      const double speed = static_cast<double>(glm::length(centres[j] - previous[j])) * clip.fps;
      if (speed > fastest.speed) fastest = {speed, static_cast<int>(j), f};
    }
    previous = std::move(centres);
  }
  return fastest;
}

std::optional<double> MaxPositionDistance(const std::vector<std::vector<glm::vec3>>& a,
                                          const std::vector<std::vector<glm::vec3>>& b) {
  if (a.size() != b.size()) return std::nullopt;
  double worst = 0.0;
  for (size_t f = 0; f < a.size(); ++f) {
    if (a[f].size() != b[f].size()) return std::nullopt;
    for (size_t j = 0; j < a[f].size(); ++j) worst = std::max(worst, double(glm::length(a[f][j] - b[f][j])));
  }
  return worst;
}

}  // namespace rise
