// SPDX-License-Identifier: MIT
#include "core/generate.h"

#include "core/biped.h"
#include "core/clip_quality.h"
#include "core/input_json.h"
#include "export/clip_resample.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>

namespace rise {
namespace {

// A hand or foot touches the ground when a contact presses with at least this force.
constexpr float kTouchForce = 1.0f;  // N

// Builds what the controller reads from the simulated biped.
void ReadBody(const Biped& biped, const physics::World& world, const BodyRig& rig,
              std::vector<physics::ContactInfo>& scratch, BodyReading& reading, double clipStart = 0.0) {
  const std::vector<physics::Transform> joints = biped.JointWorldTransforms();
  reading.time = world.Time() - clipStart;
  reading.jointPositions.resize(joints.size());
  reading.jointRotations.resize(joints.size());
  for (size_t j = 0; j < joints.size(); ++j) {
    reading.jointPositions[j] = joints[j].position;
    reading.jointRotations[j] = joints[j].rotation;
  }
  reading.com = biped.CenterOfMass();
  reading.comVelocity = biped.CenterOfMassVelocity();
  reading.maxBodySpeed = biped.MaxBodySpeed();
  reading.maxAngularSpeed = 0.0f;
  for (int j = 0; j < static_cast<int>(joints.size()); ++j) {
    const physics::BodyId body = biped.BodyOf(j);
    if (body.IsValid()) reading.maxAngularSpeed = std::max(reading.maxAngularSpeed, glm::length(world.GetAngularVelocity(body)));
  }
  for (int i = 0; i < kLimbCount; ++i) {
    world.GetGroundContacts(biped.BodyOf(rig.end[i]), scratch);
    reading.touching[i] = std::any_of(scratch.begin(), scratch.end(),
                                      [](const physics::ContactInfo& c) { return c.normalForce >= kTouchForce; });
  }
}

// Open contact intervals become ContactSpans when they close (or at the end).
struct ContactTracker {
  std::array<double, kLimbCount> since{-1.0, -1.0, -1.0, -1.0};
  std::array<bool, kLimbCount> lockedThroughout{};

  void Update(double time, const std::array<bool, kLimbCount>& touching, const std::array<bool, kLimbCount>& planted,
              std::vector<ContactSpan>& out) {
    for (int i = 0; i < kLimbCount; ++i) {
      if (touching[i] && since[i] < 0.0) since[i] = time, lockedThroughout[i] = planted[i];
      if (touching[i]) lockedThroughout[i] = lockedThroughout[i] && planted[i];
      if (!touching[i] && since[i] >= 0.0) Close(i, time, out);
    }
  }
  void Close(int i, double time, std::vector<ContactSpan>& out) {
    out.push_back({LimbName(static_cast<Limb>(i)), since[i], time, lockedThroughout[i]});
    since[i] = -1.0;
  }
};

std::string Describe(const physics::StepStatus& status, double time, const Biped& biped) {
  const int joint = biped.JointOfBody(status.firstBadBody);
  const std::string body = joint >= 0 ? biped.Def().skeleton.joints[joint].name : "?";
  char text[200];
  std::snprintf(text, sizeof text, "simulation became unstable at %.3f s (%s in body '%s')", time,
                (status.flags & physics::kStepNonFinite) ? "non-finite state" : "speed over the health limit",
                body.c_str());
  return text;
}

// A body falling in the settle (a drop at the start, or a fall before a retry) lands with its
// joints solved exactly (physics/joint_tree.h) while any of its boxes moves faster than this. The
// clip records the bones' rotations, so a joint the impact opens moves every bone below it: with
// the sequential joints' 5-8 mm per joint, a hand or foot landed on the ground showed 2.0-3.6 cm
// below it in the clip while its box was at most 0.9 cm below in the engine. Below this speed,
// and in every other phase, the joints are the sequential ones the controller was tuned on: a
// body laid on its back or front never reaches it, so those starts are unchanged bit for bit
// (settled with the exact joints throughout, prone starts on a 10 deg slope that stood fell).
// One laid on its side can topple faster than this, so side starts do change (bench/start_matrix:
// side_right, 1.50 m, 0 deg no longer stands).
constexpr float kLandingSpeed = 1.0f;  // m/s

// A posture is laid on the ground by its lowest corner, not by how it would lie: one on its side
// touched down on its top foot, dropped 5-7 cm onto its hip and shoulder and crept 3-4 cm for a
// second while the settle held it, and the clip recorded that (the top foot's slide was 4 cm of
// the 5 cm bar before the roll began). So a laid-down start is held as the settle holds a body
// (RiseController::HoldAsItLies) until it lies still, for at most this long, and the clip begins
// there. A drop (drop_height_m > 0) is recorded as it falls, and a custom start as it was given:
// it may be a crouch on the feet, which the controller takes as it stands (it would sag here).
constexpr double kMaxLayDown = 3.0;  // s

physics::JointSolver JointSolverFor(RisePhase phase, const BodyReading& reading) {
  return phase == RisePhase::kSettle && reading.maxBodySpeed > kLandingSpeed ? physics::JointSolver::kDirectTree
                                                                            : physics::JointSolver::kSequentialImpulse;
}

}  // namespace

GeneratedClip GenerateClip(const RiseSpec& spec, const GenerateSettings& settings) {
  GeneratedClip result;
  const BipedDef def = MakeBipedDef(spec.character);
  physics::World world(BipedWorldSettings());
  AddGround(world, spec.terrain);
  Biped biped(def, world, StartPose(def, spec.start, spec.terrain.slopeDeg),
              static_cast<float>(spec.terrain.friction));
  biped.SetServosEnabled(true);

  RiseController controller(biped.Def(), spec, settings.keepTrace);
  const BodyRig rig = BodyRig::FromDef(def);
  const int jointCount = def.skeleton.JointCount();
  const double dt = world.Settings().timeStep;
  const int maxSteps = static_cast<int>(std::ceil(spec.maxDurationS / dt));

  MotionSamples samples;
  samples.rotations.assign(jointCount, {});
  ClipMetadata metadata;
  std::vector<double> peakTorque(jointCount, 0.0);
  ContactTracker contacts;
  RisePhase phase = controller.Phase();
  double phaseStart = 0.0;
  BodyReading reading;
  ServoTargets targets;
  std::vector<float> appliedScale(jointCount, -1.0f);
  std::vector<physics::ContactInfo> scratch;
  // The targets to the servos, and the joint solver for the phase.
  auto drive = [&] {
    for (int j = 1; j < jointCount; ++j) {
      if (!biped.JointOf(j).IsValid()) continue;
      biped.SetLocalTarget(j, targets.local[j]);
      world.SetMotorFeedForward(biped.JointOf(j), targets.feedForward[j]);
      if (targets.gainScale[j] != appliedScale[j]) {
        const BoneDef& bone = def.bones[j];
        biped.SetServoGains(j, bone.servoKp * targets.gainScale[j], bone.servoKd * targets.gainScale[j],
                            bone.maxTorqueNm);
        appliedScale[j] = targets.gainScale[j];
      }
    }
    world.Settings().jointSolver = JointSolverFor(controller.Phase(), reading);
  };

  // The clip's time starts once a laid-down body lies still (see kMaxLayDown).
  double clipStart = 0.0;
  if (spec.start.posture != Posture::kCustom && spec.start.dropHeightM == 0.0) {
    double stillSince = -1.0;
    for (;;) {
      ReadBody(biped, world, rig, scratch, reading);
      if (!RiseController::Still(reading)) stillSince = -1.0;
      else if (stillSince < 0.0) stillSince = reading.time;
      const bool rested = stillSince >= 0.0 && reading.time - stillSince >= RiseController::kRestHold;
      if (rested || reading.time >= kMaxLayDown) break;
      controller.HoldAsItLies(reading, targets);
      drive();
      if (!world.Step().Ok()) break;  // the clip's first step reports it
    }
    clipStart = world.Time();
  }

  auto record = [&](double time) {
    const BipedPose pose = biped.Pose();
    samples.times.push_back(time);
    samples.rootTranslation.push_back(pose.root.position);
    samples.rotations[0].push_back(pose.root.rotation);
    for (int j = 1; j < jointCount; ++j) samples.rotations[j].push_back(pose.local[j]);
  };

  for (int step = 0; step <= maxSteps; ++step) {
    ReadBody(biped, world, rig, scratch, reading, clipStart);
    controller.Update(reading, targets);
    const double time = reading.time;
    record(time);
    contacts.Update(time, reading.touching, controller.Planted(), metadata.contacts);
    if (controller.Phase() != phase) {
      metadata.phases.push_back({RisePhaseName(phase), phaseStart, time});
      phase = controller.Phase();
      phaseStart = time;
    }
    if (settings.keepTrace) result.trace.push_back(controller.LastTrace());
    if (controller.Finished() || controller.GaveUp() || step == maxSteps) break;

    drive();
    for (const Disturbance& push : spec.disturbances) {
      if (time + 1e-9 >= push.timeS && time < push.timeS + push.durationS) {
        const physics::BodyId body = biped.BodyOf(def.Find(push.body));
        world.ApplyForce(body, glm::vec3(push.forceN[0], push.forceN[1], push.forceN[2]),
                         world.GetTransform(body).position);
      }
    }
    const physics::StepStatus status = world.Step();
    if (settings.keepTrace) result.trace.back().jointTorques.assign(jointCount, 0.0f);
    for (int j = 1; j < jointCount; ++j) {
      if (!biped.JointOf(j).IsValid()) continue;
      const float torque = glm::length(world.GetMotorTorque(biped.JointOf(j)));
      peakTorque[j] = std::max(peakTorque[j], static_cast<double>(torque));
      if (settings.keepTrace) result.trace.back().jointTorques[j] = torque;
    }
    if (!status.Ok()) {
      result.health = {false, Describe(status, world.Time() - clipStart, biped)};
      break;
    }
    if (settings.onProgress && step % 240 == 0) settings.onProgress(world.Time() - clipStart, spec.maxDurationS);
  }

  const double end = samples.times.back();
  metadata.phases.push_back({RisePhaseName(phase), phaseStart, end});
  for (int i = 0; i < kLimbCount; ++i) {
    if (contacts.since[i] >= 0.0) contacts.Close(i, end, metadata.contacts);
  }
  std::sort(metadata.contacts.begin(), metadata.contacts.end(),
            [](const ContactSpan& a, const ContactSpan& b) { return a.start < b.start || (a.start == b.start && a.effector < b.effector); });
  metadata.parametersJson = RiseSpecToJson(spec).dump();
  metadata.generatorVersion = RISE_VERSION;
  metadata.seed = spec.seed;
  // Cut off by max_duration_s in its stand, a body has stood once it has stood
  // for the window the quality check measures, though not yet still long enough
  // to end the clip (samples/prone.json cut at 13.6 s, 1.1 s into its stand,
  // passed every bar and was reported as "did not stand", exit 1).
  result.stood = controller.StandingFor(end, QualityOptions{}.standWindow);  // Finished() implies it
  result.timeToStand = result.stood ? controller.StandTime() : -1.0;
  metadata.timeToStand = result.timeToStand;
  for (int j = 1; j < jointCount; ++j) {
    if (biped.JointOf(j).IsValid()) metadata.peakTorques.emplace_back(def.skeleton.joints[j].name, peakTorque[j]);
  }
  result.retries = controller.Retries();
  result.simulatedSeconds = end;
  result.clip = ResampleClip(def.skeleton, samples, spec.fps, metadata);

  char outcome[160];
  if (!result.health.ok) {
    std::snprintf(outcome, sizeof outcome, "failed: %s", result.health.message.c_str());
  } else if (result.stood) {
    std::snprintf(outcome, sizeof outcome, "stood at %.2f s", result.timeToStand);
  } else if (controller.GaveUp()) {
    std::snprintf(outcome, sizeof outcome, "did not stand: fell %d times, at rest at %.2f s", controller.Retries() + 1, end);
  } else {
    std::snprintf(outcome, sizeof outcome, "did not stand within %.1f s (last phase: %s)", spec.maxDurationS,
                  RisePhaseName(controller.Phase()));
  }
  result.outcome = outcome;
  return result;
}

std::string TraceToJsonLines(const std::vector<TraceSample>& trace, const Skeleton& skeleton) {
  auto vec = [](const glm::vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); };
  std::string text;
  for (const TraceSample& sample : trace) {
    nlohmann::json line;
    line["t"] = sample.time;
    line["phase"] = RisePhaseName(sample.phase);
    line["move"] = sample.move;
    line["com"] = vec(sample.com);
    line["com_velocity"] = vec(sample.comVelocity);
    line["com_goal"] = vec(sample.comGoal);
    line["pressure"] = vec(sample.pressure);
    line["heading"] = vec(sample.heading);
    line["tracking_error"] = sample.trackingError;
    line["feet_distance"] = sample.feetDistance;
    if (sample.rollSide != 0.0f) {
      line["roll"] = {{"side", sample.rollSide > 0.0f ? "left" : "right"},
                      {"pelvis_deg", glm::degrees(sample.pelvisRoll)},
                      {"chest_deg", glm::degrees(sample.chestRoll)}};
    } else {
      line["roll"] = nullptr;
    }
    nlohmann::json support = nlohmann::json::array();
    for (const glm::vec2& p : sample.support.hull) support.push_back({p.x, p.y});
    line["support"] = support;
    for (int i = 0; i < kLimbCount; ++i) {
      nlohmann::json limb;
      limb["target"] = vec(sample.limbTargets[i]);
      limb["at"] = vec(sample.limbPositions[i]);
      limb["clearance"] = sample.clearance[i];
      limb["touching"] = sample.touching[i];
      limb["planted"] = sample.planted[i];
      limb["load"] = sample.load[i];
      line[LimbName(static_cast<Limb>(i))] = limb;
    }
    nlohmann::json torques = nlohmann::json::object();
    for (size_t j = 1; j < sample.jointTorques.size(); ++j) {
      if (skeleton.joints[j].hasBox) torques[skeleton.joints[j].name] = sample.jointTorques[j];
    }
    line["torques"] = torques;
    text += line.dump() + "\n";
  }
  return text;
}

}  // namespace rise
