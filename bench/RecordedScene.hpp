// Scene S1 as scripts/benchmarks/record_s1_scene.py recorded it (bench/data): 250 gummy bears and the box's five YADE
// Walls, with S1's materials, as a ContactModel; the settled packing's states; two trajectories from it, the first
// steps of shaking and as many steps in the standing box; and as many steps of a whole S1 run's landing window
// (from t = 0.45 s, seed 1: the falling bears meeting the shaken pile). Lets the benchmark and the tests run the
// complete contact step on a real packing, without YADE or Python.
#pragma once

#include <string>
#include <vector>

#include "pkg/engine/ContactData.hpp"

namespace roundedmesh {

struct RecordedScene {
  ContactModel model;
  std::vector<BodyState> bodyStates;     // settled packing, in the model's body order
  std::vector<BodyState> partnerStates;  // the walls
  // trajectory[k]: every body's state at step k, then the floor's (partner 0).
  using Trajectory = std::vector<std::vector<BodyState>>;
  Trajectory shaking, resting, landing;

  // Puts the settled packing into data.
  void setStates(ContactData& data) const;
  // Puts step k of a trajectory into data.
  void setStates(ContactData& data, const Trajectory& trajectory, int k) const;
};

// A pair of the scene's bodies as the engine's pairGeometry places it for the narrow phase: body 2's pose in body 1's
// frame (x1 = rotation * x2 + translation), its motion relative to body 1, and the Hertz range `shallow` [m], so that
// tests and benchmarks can call Ig2 on the pair's candidate list directly.
struct BodyPairFrame {
  Matrix3r rotation;
  Vector3r translation;
  RelativeMotion motion;
  Real shallow;
};
BodyPairFrame bodyPairFrame(const ContactModel& model, const ContactData& data, const BodyPair& pair);

// Frames 0, 1, ..., n-1, n-2, ..., 1, 0, 1, ... of a trajectory of n frames at steps 0, 1, 2, ...: the recorded
// motion forth and back, without a jump.
int frameAt(long step, int frames);

// Reads bench/data (ROUNDEDMESH_BENCH_DATA at build time, or `folder`). Throws std::runtime_error naming the
// file on a missing or malformed one.
RecordedScene loadRecordedScene(const std::string& folder = ROUNDEDMESH_BENCH_DATA);

}  // namespace roundedmesh
