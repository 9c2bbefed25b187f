// SPDX-License-Identifier: MIT
// Side by side (issue 7): the 15-box ragdoll drop of scenes/ragdoll_drop in our engine and, when
// built with -DRISE_BENCH_PEERS=ON, in Bullet, ODE and MuJoCo, all in one run and one table.
//
// For every engine: one untimed quality run that measures after every step, then `reps` timed
// runs from scratch (thread CPU time of the step loop only; the median is printed). Quality is
// measured identically for all engines from their box poses: penetration = depth of the deepest
// box corner below y = 0; joint separation = distance between the joint anchor carried by the
// parent and the one carried by the child.
//
// Rows "ours" (the default WorldSettings, which rise-gen uses) and "ours_fast"
// (scenes::FastDropSettings(), the configuration that meets issue 7's targets) are always printed.
//
// Usage: ragdoll_compare [--reps N] [--engine NAME] [--substeps N] [--iterations N] [--direct] [--callgrind]
//   --substeps N adds a row "ours_<N>sub": our engine with N sub-steps instead of 4 (what fewer
//                sub-steps would buy, and cost in quality).
//   --iterations N  gives those extra rows N biased solve passes per sub-step instead of 1
//                ("ours_<N>sub_<M>it").
//   --direct     adds the same rows with JointSolver::kDirectTree ("ours_direct", "ours_<N>sub_direct").
//   --callgrind  re-runs each engine's timed loop under valgrind's callgrind (collecting only
//                inside RunSteps) and adds instructions per step; the same figure by hand:
//   valgrind --tool=callgrind --collect-atstart=no --toggle-collect='*RunSteps*'
//            --callgrind-out-file=out.cg ragdoll_compare --engine ours --reps 1 --timing-only
//   (one command line), then instructions per step = the "totals:" line of out.cg / 1200.
#include "bench/ragdoll_engine.h"

#include "physics/world.h"
#include "scenes/ragdoll_drop.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace rise::bench {

namespace {

// Sub-steps of the extra "ours_<n>sub" row (--substeps); 0 = no such row.
int gExtraSubsteps = 0;
// Biased solve passes per sub-step of the extra rows (--iterations); 0 = the default.
int gExtraIterations = 0;
// Adds rows with the direct joint-tree solver (--direct).
bool gDirect = false;

class RiseRagdoll final : public RagdollEngine {
 public:
  RiseRagdoll(const scenes::RagdollScene& scene, const physics::WorldSettings& settings) : world_(settings) {
    built_ = scenes::BuildRagdollDrop(scene, world_);
  }
  void Step() override { world_.Step(); }
  BoxState Box(int box) override {
    const physics::Transform& t = world_.GetTransform(built_.bodies[box]);
    return BoxState{t.position, t.rotation, world_.GetLinearVelocity(built_.bodies[box])};
  }

 private:
  physics::World world_;
  scenes::BuiltRagdoll built_;
};

// The defaults with `timeStep`; substeps > 0 replaces the sub-step count (and then --iterations
// the solve count).
physics::WorldSettings OurSettings(float timeStep, int substeps, physics::JointSolver jointSolver) {
  physics::WorldSettings settings;
  settings.timeStep = timeStep;
  if (substeps > 0) settings.substepCount = substeps;
  if (substeps > 0 && gExtraIterations > 0) settings.solveIterations = gExtraIterations;
  settings.jointSolver = jointSolver;
  return settings;
}

std::unique_ptr<RagdollEngine> MakeRiseRagdoll(const scenes::RagdollScene& scene, float timeStep) {
  return std::make_unique<RiseRagdoll>(scene, OurSettings(timeStep, 0, physics::JointSolver::kSequentialImpulse));
}

std::unique_ptr<RagdollEngine> MakeRiseRagdollFast(const scenes::RagdollScene& scene, float timeStep) {
  physics::WorldSettings settings = scenes::FastDropSettings();
  settings.timeStep = timeStep;
  return std::make_unique<RiseRagdoll>(scene, settings);
}

std::unique_ptr<RagdollEngine> MakeRiseRagdollExtraSubsteps(const scenes::RagdollScene& scene, float timeStep) {
  return std::make_unique<RiseRagdoll>(scene,
                                       OurSettings(timeStep, gExtraSubsteps, physics::JointSolver::kSequentialImpulse));
}

std::unique_ptr<RagdollEngine> MakeRiseRagdollDirect(const scenes::RagdollScene& scene, float timeStep) {
  return std::make_unique<RiseRagdoll>(scene, OurSettings(timeStep, 0, physics::JointSolver::kDirectTree));
}

std::unique_ptr<RagdollEngine> MakeRiseRagdollExtraSubstepsDirect(const scenes::RagdollScene& scene, float timeStep) {
  return std::make_unique<RiseRagdoll>(scene, OurSettings(timeStep, gExtraSubsteps, physics::JointSolver::kDirectTree));
}

struct EngineEntry {
  std::string name;      // as printed and as given to --engine
  std::string settings;  // printed under the table
  std::unique_ptr<RagdollEngine> (*make)(const scenes::RagdollScene& scene, float timeStep);
};

std::vector<EngineEntry> Engines() {
  std::vector<EngineEntry> engines = {
      {"ours", "rise physics, WorldSettings defaults: 4 sub-steps, 1 solve + 1 relax each", MakeRiseRagdoll},
      {"ours_fast", "rise physics, scenes::FastDropSettings(): direct joint tree, 1 sub-step, 3 solves + 1 relax",
       MakeRiseRagdollFast}};
  const std::string n = std::to_string(gExtraSubsteps);
  const std::string it = gExtraIterations > 0 ? "_" + std::to_string(gExtraIterations) + "it" : "";
  const std::string itText = gExtraIterations > 0 ? ", " + std::to_string(gExtraIterations) + " solves" : "";
  if (gExtraSubsteps > 0) {
    engines.push_back({"ours_" + n + "sub" + it,
                       "ours with " + n + " sub-steps instead of 4" + itText + " (--substeps; not the default)",
                       MakeRiseRagdollExtraSubsteps});
  }
  if (gDirect) {
    engines.push_back({"ours_direct", "ours with the direct joint-tree solver (--direct; not the default)",
                       MakeRiseRagdollDirect});
    if (gExtraSubsteps > 0) {
      engines.push_back({"ours_" + n + "sub" + it + "_direct",
                         "ours with " + n + " sub-steps" + itText + " and the direct joint-tree solver",
                         MakeRiseRagdollExtraSubstepsDirect});
    }
  }
#ifdef RISE_BENCH_PEERS
  engines.push_back({"bullet", "Bullet 3.24 float, sequential impulse, 10 iterations, sleeping off", MakeBulletRagdoll});
  engines.push_back({"ode", "ODE 0.16.2 double, quickstep 20 iterations, ERP 0.2, 4 contacts/pair", MakeOdeRagdoll});
  engines.push_back({"mujoco", "MuJoCo 2.2.2 double, defaults (Euler, Newton, pyramidal cone)", MakeMujocoRagdoll});
#endif
  return engines;
}

struct Quality {
  float peakPenetration = 0.0f;  // m
  float peakSeparation = 0.0f;   // m
  float finalPelvisHeight = 0.0f;  // m
  float finalMaxSpeed = 0.0f;    // m/s, fastest box centre
  bool finite = true;
};

// The joint's anchor as carried by box `box` (frames are axis-aligned at the bind pose).
glm::vec3 AnchorOn(const scenes::RagdollScene& scene, const BoxState& state, int box, const glm::vec3& bindAnchor) {
  return state.position + state.rotation * (bindAnchor - scene.boxes[box].center);
}

void Measure(const scenes::RagdollScene& scene, RagdollEngine& engine, Quality& quality) {
  std::vector<BoxState> states;
  for (int i = 0; i < int(scene.boxes.size()); ++i) states.push_back(engine.Box(i));
  for (int i = 0; i < int(scene.boxes.size()); ++i) {
    const glm::vec3 h = scene.boxes[i].halfExtents;
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 sign((corner & 1) ? 1.0f : -1.0f, (corner & 2) ? 1.0f : -1.0f, (corner & 4) ? 1.0f : -1.0f);
      const float y = (states[i].position + states[i].rotation * (sign * h)).y;
      quality.peakPenetration = std::max(quality.peakPenetration, -y);
    }
    quality.finite = quality.finite && std::isfinite(states[i].position.x + states[i].position.y + states[i].position.z);
  }
  for (const scenes::RagdollJoint& joint : scene.joints) {
    const glm::vec3 onParent = AnchorOn(scene, states[joint.parent], joint.parent, joint.anchor);
    const glm::vec3 onChild = AnchorOn(scene, states[joint.child], joint.child, joint.anchor);
    quality.peakSeparation = std::max(quality.peakSeparation, glm::length(onChild - onParent));
  }
  quality.finalPelvisHeight = states[0].position.y;
  quality.finalMaxSpeed = 0.0f;
  for (const BoxState& state : states) quality.finalMaxSpeed = std::max(quality.finalMaxSpeed, glm::length(state.velocity));
}

// The only code callgrind collects in (see the file comment); kept out of line so it exists.
__attribute__((noinline)) void RunSteps(RagdollEngine& engine, int steps) {
  for (int i = 0; i < steps; ++i) engine.Step();
}

double ThreadSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Median thread CPU seconds of `reps` runs of the whole drop, each from a freshly built scene.
double MedianSeconds(const EngineEntry& entry, const scenes::RagdollScene& scene, float timeStep, int steps, int reps) {
  std::vector<double> seconds;
  for (int rep = 0; rep < reps; ++rep) {
    std::unique_ptr<RagdollEngine> engine = entry.make(scene, timeStep);
    const double start = ThreadSeconds();
    RunSteps(*engine, steps);
    seconds.push_back(ThreadSeconds() - start);
  }
  std::sort(seconds.begin(), seconds.end());
  return seconds[seconds.size() / 2];
}

// Instructions per step of `engine` under callgrind (0 when valgrind is missing or fails).
double CallgrindInstructionsPerStep(const std::string& engine, int substeps, int steps) {
  char self[4096] = {};
  if (readlink("/proc/self/exe", self, sizeof(self) - 1) <= 0) return 0.0;
  const std::string out = "/tmp/ragdoll_compare." + std::to_string(getpid()) + "." + engine + ".cg";
  const std::string command = "valgrind --tool=callgrind --collect-atstart=no --toggle-collect='*RunSteps*' "
                              "--callgrind-out-file=" + out + " '" + self + "' --engine " + engine +
                              " --substeps " + std::to_string(substeps) + " --iterations " +
                              std::to_string(gExtraIterations) + (gDirect ? " --direct" : "") +
                              " --reps 1 --timing-only > /dev/null 2>&1";
  if (std::system(command.c_str()) != 0) return 0.0;
  std::ifstream file(out);
  std::string line;
  double total = 0.0;
  while (std::getline(file, line)) {
    if (line.rfind("totals:", 0) == 0) total = std::atof(line.c_str() + 7);
  }
  std::remove(out.c_str());
  return total / steps;
}

}  // namespace

}  // namespace rise::bench

int main(int argc, char** argv) {
  using namespace rise::bench;
  int reps = 7;
  std::string only;
  bool callgrind = false;
  bool timingOnly = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--reps" && i + 1 < argc) {
      reps = std::max(1, std::atoi(argv[++i]));
    } else if (arg == "--engine" && i + 1 < argc) {
      only = argv[++i];
    } else if (arg == "--substeps" && i + 1 < argc) {
      gExtraSubsteps = std::max(0, std::atoi(argv[++i]));
    } else if (arg == "--iterations" && i + 1 < argc) {
      gExtraIterations = std::max(0, std::atoi(argv[++i]));
    } else if (arg == "--direct") {
      gDirect = true;
    } else if (arg == "--callgrind") {
      callgrind = true;
    } else if (arg == "--timing-only") {
      timingOnly = true;
    } else {
      std::fprintf(stderr, "usage: %s [--reps N] [--engine NAME] [--substeps N] [--iterations N] [--direct] [--callgrind] [--timing-only]\n", argv[0]);
      return 2;
    }
  }

  const rise::scenes::RagdollScene scene = rise::scenes::MakeRagdollDropScene();
  const float timeStep = 1.0f / 240.0f;
  const int steps = int(scene.simulatedSeconds / timeStep + 0.5f);
  std::vector<EngineEntry> engines = Engines();
  if (!only.empty()) {
    engines.erase(std::remove_if(engines.begin(), engines.end(), [&](const EngineEntry& e) { return only != e.name; }),
                  engines.end());
    if (engines.empty()) {
      std::fprintf(stderr, "no engine named '%s' in this build\n", only.c_str());
      return 2;
    }
  }
  if (timingOnly) {
    for (const EngineEntry& entry : engines) MedianSeconds(entry, scene, timeStep, steps, reps);
    return 0;
  }

  std::printf("ragdoll drop: %zu boxes, %zu joints, drop %.1f m, friction %.1f, %d steps of 1/240 s, median of %d\n",
              scene.boxes.size(), scene.joints.size(), double(scene.dropHeight), double(scene.friction), steps, reps);
  std::printf("%-20s %9s %9s %12s %12s %10s %10s %12s\n", "engine", "us/step", "x_real", "penetr_mm", "joint_sep_mm",
              "pelvis_y_m", "max_v_m/s", "instr/step");
  bool allFinite = true;
  for (const EngineEntry& entry : engines) {
    Quality quality;
    {
      std::unique_ptr<RagdollEngine> engine = entry.make(scene, timeStep);
      for (int i = 0; i < steps; ++i) {
        engine->Step();
        Measure(scene, *engine, quality);
      }
    }
    allFinite = allFinite && quality.finite;
    const double seconds = MedianSeconds(entry, scene, timeStep, steps, reps);
    const double instructions = callgrind ? CallgrindInstructionsPerStep(entry.name, gExtraSubsteps, steps) : 0.0;
    char instructionText[32] = "-";
    if (instructions > 0.0) std::snprintf(instructionText, sizeof(instructionText), "%.0f", instructions);
    std::printf("%-20s %9.2f %9.0f %12.2f %12.2f %10.4f %10.4f %12s%s\n", entry.name.c_str(), 1e6 * seconds / steps,
                double(steps) * double(timeStep) / seconds, 1000.0 * double(quality.peakPenetration),
                1000.0 * double(quality.peakSeparation), double(quality.finalPelvisHeight),
                double(quality.finalMaxSpeed), instructionText, quality.finite ? "" : "  (non-finite state)");
    std::fflush(stdout);
  }
  for (const EngineEntry& entry : engines) std::printf("  %-20s %s\n", entry.name.c_str(), entry.settings.c_str());
  return allFinite ? 0 : 1;
}
