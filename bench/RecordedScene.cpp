#include "bench/RecordedScene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "pkg/engine/PairGeometry.hpp"
#include "pkg/meshing/BodyMesh.hpp"
#include "pkg/shape/PrincipalCurvature.hpp"
#include "pkg/shape/TriangleSurface.hpp"

namespace roundedmesh {
namespace {

// S1's materials (doc/scenes.md): particles and box, normal damping A = 0.01 s, no friction.
const HertzMaterial kParticle{1e6, 0.4, 2000, 0.01};
const HertzMaterial kBox{5e6, 0.4, 2000, 0.01};

[[noreturn]] void malformed(const std::string& path, const std::string& what) {
  throw std::runtime_error(path + ": " + what);
}

std::ifstream open(const std::string& path, std::ios::openmode mode = std::ios::in) {
  std::ifstream in(path, mode);
  if (!in) malformed(path, "cannot be read (run scripts/benchmarks/record_s1_scene.py)");
  return in;
}

// "vertices n", n lines of x y z; "triangles m", m lines of a b c; "radii m", m lines of r.
BodyMesh readMesh(const std::string& path) {
  std::ifstream in = open(path);
  std::string line, word;
  auto section = [&](const char* name) {
    while (std::getline(in, line) && line.rfind("#", 0) == 0) {
    }
    std::istringstream header(line);
    size_t count = 0;
    if (!(header >> word >> count) || word != name) malformed(path, std::string("expected the section '") + name + "'");
    return count;
  };
  std::vector<Vector3r> vertices(section("vertices"));
  for (Vector3r& v : vertices)
    if (!(in >> v.x() >> v.y() >> v.z())) malformed(path, "truncated vertices");
  in.ignore(1);
  std::vector<Triangle> triangles(section("triangles"));
  for (Triangle& t : triangles)
    if (!(in >> t[0] >> t[1] >> t[2])) malformed(path, "truncated triangles");
  in.ignore(1);
  std::vector<Real> radii(section("radii"));
  for (Real& r : radii)
    if (!(in >> r)) malformed(path, "truncated radii");
  std::vector<Real> curvatures(radii.size());
  for (size_t t = 0; t < radii.size(); ++t) curvatures[t] = 1 / radii[t];
  // The file keeps the radii only: both principal curvatures are estimated from the mesh, as for a computed one.
  std::vector<PrincipalCurvature> principal = principalCurvatures(TriangleSurface{vertices, triangles});
  const RoundedMesh mesh(std::move(vertices), std::move(triangles), radii, std::move(principal));
  return BodyMesh(mesh, Vector3r::Zero(), Quaternionr::Identity(),
                  {curvatures, CurvatureSource::Prescribed, *std::max_element(radii.begin(), radii.end())});
}

BodyState state(const double* v) {
  BodyState s;
  s.position = Vector3r(v[0], v[1], v[2]);
  s.orientation = Quaternionr(v[3], v[4], v[5], v[6]).normalized();
  s.velocity = Vector3r(v[7], v[8], v[9]);
  s.angularVelocity = Vector3r(v[10], v[11], v[12]);
  return s;
}

RecordedScene::Trajectory readTrajectory(const std::string& path, size_t expectedBodies) {
  std::ifstream bin = open(path, std::ios::binary);
  const std::string magic = "roundedmesh trajectory 1\n";
  std::string read(magic.size(), '\0');
  std::int32_t bodies = 0, steps = 0;
  double dt = 0;
  bin.read(read.data(), read.size());
  bin.read(reinterpret_cast<char*>(&bodies), 4).read(reinterpret_cast<char*>(&steps), 4).read(reinterpret_cast<char*>(&dt), 8);
  if (!bin || read != magic || bodies != static_cast<int>(expectedBodies) || steps < 2)
    malformed(path, "not a trajectory of the settled packing's bodies and floor");
  std::vector<std::int32_t> ids(bodies);
  bin.read(reinterpret_cast<char*>(ids.data()), 4 * bodies);
  std::vector<float> frame(13 * bodies);
  RecordedScene::Trajectory trajectory;
  for (int k = 0; k < steps; ++k) {
    if (!bin.read(reinterpret_cast<char*>(frame.data()), 4 * frame.size())) malformed(path, "truncated");
    std::vector<BodyState>& states = trajectory.emplace_back(bodies);
    for (int b = 0; b < bodies; ++b) {
      double v[13];
      for (int i = 0; i < 13; ++i) v[i] = frame[13 * b + i];
      states[b] = state(v);
    }
  }
  return trajectory;
}

}  // namespace

void RecordedScene::setStates(ContactData& data) const {
  data.resize(model);
  data.bodyStates = bodyStates;
  data.partnerStates = partnerStates;
}

void RecordedScene::setStates(ContactData& data, const Trajectory& trajectory, int k) const {
  data.resize(model);
  const std::vector<BodyState>& frame = trajectory[k];
  std::copy(frame.begin(), frame.begin() + bodyStates.size(), data.bodyStates.begin());
  data.partnerStates = partnerStates;
  data.partnerStates[0] = frame.back();
}

int frameAt(long step, int frames) {
  const long period = 2 * (frames - 1);
  const long k = step % period;
  return static_cast<int>(k < frames ? k : period - k);
}

RecordedScene loadRecordedScene(const std::string& folder) {
  RecordedScene scene;
  const BodyMesh bear = readMesh(folder + "/gummy_bear.mesh");

  const std::string settled = folder + "/s1_settled.csv";
  std::ifstream in = open(settled);
  std::string line;
  bool header = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      header = true;
      continue;
    }
    std::istringstream fields(line);
    std::string id, shape, value;
    std::getline(fields, id, ',');
    std::getline(fields, shape, ',');
    double v[13];
    for (double& x : v) {
      if (!std::getline(fields, value, ',')) malformed(settled, "a row with fewer than 15 columns: " + line);
      x = std::stod(value);
    }
    if (shape == "gummy_bear") {
      scene.model.bodies.push_back(roundedBody(std::stoi(id), bear, kParticle));
      scene.bodyStates.push_back(state(v));
    } else if (shape.size() == 6 && shape.rfind("wall", 0) == 0) {
      scene.model.partners.push_back({std::stoi(id), Wall{shape[4] - 'x', shape[5] == '+' ? 1 : -1}, kBox});
      scene.partnerStates.push_back(state(v));
    } else {
      malformed(settled, "unknown shape '" + shape + "'");
    }
  }
  if (scene.model.partners.empty() || std::get<Wall>(scene.model.partners[0].shape).axis != 2)
    malformed(settled, "the floor (wallz+) must be the first wall");

  scene.shaking = readTrajectory(folder + "/s1_shaking.bin", scene.bodyStates.size() + 1);
  scene.resting = readTrajectory(folder + "/s1_resting.bin", scene.bodyStates.size() + 1);
  scene.landing = readTrajectory(folder + "/s1_landing.bin", scene.bodyStates.size() + 1);
  return scene;
}

BodyPairFrame bodyPairFrame(const ContactModel& model, const ContactData& data, const BodyPair& pair) {
  const BodyState &s1 = data.bodyStates[pair.body], &s2 = data.bodyStates[pair.other];
  const Matrix3r toBody = s1.orientation.toRotationMatrix().transpose();
  return {(s1.orientation.conjugate() * s2.orientation).toRotationMatrix(), toBody * (s2.position - s1.position),
          relativeMotion(s1, s2, toBody),
          kDeepestOverlap * std::min(model.bodies[pair.body].equivalentRadius, model.bodies[pair.other].equivalentRadius)};
}

}  // namespace roundedmesh
