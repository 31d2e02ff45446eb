// The contact engine as the Python package drives it (roundedmesh/scene.py), and plane_contact,
// sphere_contact and body_contact (pkg/engine/PairEvaluation.hpp): arguments checked and converted here.
#include <boost/python.hpp>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>

#include "pkg/engine/CriticalTimeStep.hpp"
#include "pkg/engine/PairEvaluation.hpp"
#include "pkg/engine/RoundedMeshEngine.hpp"
#include "pkg/engine/StopRules.hpp"
#include "pkg/shape/BodyMesh.hpp"
#include "py/module/NumpyConversion.hpp"
#include "py/module/YadeBridge.hpp"

namespace roundedmesh::python {
namespace {

PressureOptions pressureOptions(Real gamma, const std::string& regime, const std::string& curvature) {
  if (!(std::isfinite(gamma) && gamma > 0))
    throw std::invalid_argument("gamma must be positive and finite, got " + std::to_string(gamma));
  PressureOptions options;
  options.gamma = gamma;
  if (regime == "auto")
    options.regime = RegimeChoice::Auto;
  else if (regime == "quadrature")
    options.regime = RegimeChoice::Quadrature;
  else if (regime == "direct")
    options.regime = RegimeChoice::Direct;
  else
    throw std::invalid_argument("regime must be 'auto', 'quadrature' or 'direct', got '" + regime + "'");
  if (curvature == "mean")
    options.curvature = CurvatureModel::Mean;
  else if (curvature == "principal")
    options.curvature = CurvatureModel::Principal;
  else
    throw std::invalid_argument("curvature must be 'mean' or 'principal', got '" + curvature + "'");
  return options;
}

FrictionLaw frictionLaw(const std::string& friction) {
  if (friction == "spring") return FrictionLaw::Spring;
  if (friction == "viscous") return FrictionLaw::Viscous;
  throw std::invalid_argument("friction must be 'spring' or 'viscous', got '" + friction + "'");
}

std::vector<Real> toReals(const bp::object& sequence, size_t expected) {
  if (static_cast<size_t>(bp::len(sequence)) != expected)
    throw std::invalid_argument("expected " + std::to_string(expected) + " masses");
  std::vector<Real> values(expected);
  for (size_t i = 0; i < expected; ++i) values[i] = bp::extract<Real>(sequence[i]);
  return values;
}

constexpr const char* kSpringHeader = "RMSPRING1";
constexpr size_t kSpringRecord = 2 * sizeof(std::int32_t) + 8 * sizeof(Real);

std::vector<Vector3r> toVectors(const bp::object& sequence, size_t expected) {
  if (static_cast<size_t>(bp::len(sequence)) != expected)
    throw std::invalid_argument("expected " + std::to_string(expected) + " moments of inertia");
  std::vector<Vector3r> values(expected);
  for (size_t i = 0; i < expected; ++i) values[i] = bp::extract<Vector3r>(sequence[i]);
  return values;
}

class Engine {
 public:
  void addBody(int id, const BodyMesh& mesh, const HertzMaterial& material) {
    model_.bodies.push_back(roundedBody(id, mesh, material));
  }
  void addPartner(const bp::object& body, const HertzMaterial& material) {
    const int id = bp::extract<int>(body.attr("id"));
    model_.partners.push_back({id, yadeShape(body, id), material});
  }
  // A sphere body (rm.add_sphere): a YADE Sphere whose contacts with every partner the engine computes too.
  void addSphere(const bp::object& body, const HertzMaterial& material) {
    const int id = bp::extract<int>(body.attr("id"));
    model_.partners.push_back({id, sphereShape(body, id), material, true});
  }
  void setOptions(Real gamma, const std::string& regime, const std::string& friction, Real stopOverlap,
                  const std::string& curvature) {
    if (!(stopOverlap > 0))
      throw std::invalid_argument("stop_overlap must be positive (math.inf: never), got " + std::to_string(stopOverlap));
    model_.pressure = pressureOptions(gamma, regime, curvature);
    model_.friction = frictionLaw(friction);
    model_.stopOverlap = stopOverlap;
  }

  // One contact step on the current YADE scene; returns the ids of managed bodies that have left it (and
  // then applies nothing). A step that breaks a stop rule (StopRules.hpp; stops()) applies nothing either and is
  // not kept: the next call compares with the same last step.
  bp::list step(const bp::object& omega) {
    const auto start = std::chrono::steady_clock::now();
    bp::list missing;
    data_.stops.clear();
    for (int id : readScene(omega, model_, data_)) missing.append(id);
    if (bp::len(missing) > 0) return missing;
    const auto read = std::chrono::steady_clock::now();
    RoundedMeshEngine(model_, data_);
    checkStopRules(model_, data_);
    fastest_ = fastestBody(model_, data_, bp::extract<Real>(omega.attr("dt")));
    const auto computed = std::chrono::steady_clock::now();
    if (!data_.stops.empty()) return missing;
    commitStep(data_);
    applyWrenches(omega, model_, data_);
    readMs_ = std::chrono::duration<Real, std::milli>(read - start).count();
    writeMs_ = std::chrono::duration<Real, std::milli>(std::chrono::steady_clock::now() - computed).count();
    return missing;
  }

  // (time step [s], YADE id of the body, YADE id of the other body, whether the limit is the tangential
  // contact's) of the most restrictive pair, for the masses and principal moments of inertia the bodies have in
  // YADE now (a partner's mass 0 if it does not move under forces).
  // With impactSpeed [m/s] > 0, also the step that resolves an impact at that speed (impactTimeStep).
  bp::tuple stabilityLimit(const bp::object& bodyMasses, const bp::object& partnerMasses,
                           const bp::object& bodyInertias, const bp::object& partnerInertias, Real impactSpeed) const {
    const StabilityLimit limit = roundedmesh::stabilityLimit(
        model_, toReals(bodyMasses, model_.bodies.size()), toReals(partnerMasses, model_.partners.size()),
        toVectors(bodyInertias, model_.bodies.size()), toVectors(partnerInertias, model_.partners.size()),
        impactSpeed);
    if (limit.body < 0) return bp::make_tuple(limit.timeStep, -1, -1, false);
    return bp::make_tuple(limit.timeStep, yadeId(limit.body), yadeId(limit.other), limit.tangential);
  }

  // The tangential springs of the last step (TangentialSpring.hpp), as bytes: "RMSPRING1" then, per spring, the
  // YADE ids of the pair (two int32, the pair's own order) and eight doubles: displacement (3), twist, normal (3),
  // energy, in the machine's byte order. None if there is none.
  bp::object springs() const {
    const auto active = data_.activeSprings();
    if (active.empty()) return bp::object();
    std::string bytes(kSpringHeader);
    bytes.reserve(bytes.size() + active.size() * kSpringRecord);
    for (const auto& [pair, spring] : active) {
      const std::int32_t ids[2] = {yadeId(pair.body), yadeId(pair.other)};
      const Real values[8] = {spring.displacement.x(), spring.displacement.y(), spring.displacement.z(), spring.twist,
                              spring.normal.x(),       spring.normal.y(),       spring.normal.z(),       spring.energy};
      bytes.append(reinterpret_cast<const char*>(ids), sizeof ids);
      bytes.append(reinterpret_cast<const char*>(values), sizeof values);
    }
    return bp::object(bp::handle<>(PyBytes_FromStringAndSize(bytes.data(), static_cast<Py_ssize_t>(bytes.size()))));
  }

  // Replaces the springs by those of `record` (bytes from springs(), or None for none): the next step hands each
  // pair its own. Pairs whose bodies the engine does not know (erased since) are dropped.
  void restoreSprings(const bp::object& record) {
    std::vector<std::pair<BodyPair, TangentialSpring>> springs;
    if (!record.is_none()) {
      const std::string bytes = bp::extract<std::string>(record);
      const size_t header = std::string(kSpringHeader).size();
      if (bytes.compare(0, header, kSpringHeader) != 0 || (bytes.size() - header) % kSpringRecord != 0)
        throw std::invalid_argument("the scene's tangential springs (O.tags['roundedmesh.springs']) are damaged");
      std::map<int, int> index;
      for (size_t b = 0; b < model_.bodies.size(); ++b) index[model_.bodies[b].id] = static_cast<int>(b);
      for (size_t p = 0; p < model_.partners.size(); ++p)
        index[model_.partners[p].id] = static_cast<int>(model_.bodies.size() + p);
      for (size_t at = header; at < bytes.size(); at += kSpringRecord) {
        std::int32_t ids[2];
        Real values[8];
        std::memcpy(ids, bytes.data() + at, sizeof ids);
        std::memcpy(values, bytes.data() + at + sizeof ids, sizeof values);
        const auto first = index.find(ids[0]), second = index.find(ids[1]);
        if (first == index.end() || second == index.end()) continue;
        TangentialSpring spring;
        spring.displacement = Vector3r(values[0], values[1], values[2]);
        spring.twist = values[3];
        spring.normal = Vector3r(values[4], values[5], values[6]);
        spring.energy = values[7];
        springs.push_back({{first->second, second->second}, spring});
      }
    }
    data_.restoreSprings(std::move(springs));
  }

  // Why the last step was not kept, worst first: (cause 'crossed' or 'overlap', YADE id of the body, of the other
  // side, the pair's deepest overlap [m], the size it is measured by [m], where: the pair's centre of pressure [m]).
  bp::list stops() const {
    bp::list listed;
    for (const StopReason& s : data_.stops)
      listed.append(bp::make_tuple(s.cause == StopCause::CentreCrossed ? "crossed" : "overlap", yadeId(s.body),
                                   yadeId(s.other), s.overlap, s.size, s.point));
    return listed;
  }

  // The body that moved fastest for its contact depth in the last step: (YADE id or -1, speed [m/s], speed * O.dt
  // over its contact depth kDeepestOverlap * size, that depth [m]).
  bp::tuple fastest() const {
    if (fastest_.body < 0) return bp::make_tuple(-1, 0.0, 0.0, 0.0);
    return bp::make_tuple(yadeId(fastest_.body), fastest_.speed, fastest_.fraction,
                          kDeepestOverlap * sideSize(model_, fastest_.body));
  }

  // Every pair of the last step with at least one triangle contact, as arrays with one row per pair
  // (roundedmesh.contacts()).
  bp::dict contacts() const {
    std::vector<long> id1, id2, count, sliding;
    std::vector<Vector3r> force1, torque1, force2, torque2, point, normal;
    std::vector<Real> overlap, depth;
    for (size_t k = 0; k < data_.pairs.size(); ++k) {
      const PairResult& r = data_.pairResults[k];
      if (r.summary.triangleContacts == 0) continue;
      id1.push_back(yadeId(data_.pairs[k].body));
      id2.push_back(yadeId(data_.pairs[k].other));
      force1.push_back(r.onBody.force);
      torque1.push_back(r.onBody.torque);
      force2.push_back(r.onOther.force);
      torque2.push_back(r.onOther.torque);
      point.push_back(r.summary.point);
      normal.push_back(r.summary.normal);
      overlap.push_back(r.summary.deepestOverlap);
      depth.push_back(r.summary.depth);
      count.push_back(r.summary.triangleContacts);
      sliding.push_back(r.summary.sliding);
    }
    bp::dict d;
    d["id1"] = toArray(id1);
    d["id2"] = toArray(id2);
    d["force1"] = toArray(force1);
    d["torque1"] = toArray(torque1);
    d["force2"] = toArray(force2);
    d["torque2"] = toArray(torque2);
    d["point"] = toArray(point);
    d["normal"] = toArray(normal);
    d["overlap"] = toArray(overlap);
    d["depth"] = toArray(depth);
    d["triangle_contacts"] = toArray(count);
    d["sliding"] = toArray(sliding).astype(np::dtype::get_builtin<bool>());
    return d;
  }

  // (elastic energy [J], power of normal damping [W], power of friction [W]) of the last step's contacts.
  bp::tuple energy() const {
    PairSummary total;
    for (size_t k = 0; k < data_.pairs.size(); ++k) {
      const PairSummary& s = data_.pairResults[k].summary;
      total.elasticEnergy += s.elasticEnergy;
      total.dampingPower += s.dampingPower;
      total.frictionPower += s.frictionPower;
    }
    return bp::make_tuple(total.elasticEnergy, total.dampingPower, total.frictionPower);
  }

  // {YADE id: (n_triangles, 3) array} of the contact force [N] each triangle of a rounded body received in the
  // last step, for the bodies that touched anything; empty unless keep_triangle_contacts was set before it.
  bp::dict triangleForces() const {
    std::map<int, std::vector<Vector3r>> forces;
    auto add = [&](int index, int triangle, const Vector3r& force) {
      std::vector<Vector3r>& f = forces[index];
      if (f.empty()) f.assign(model_.bodies[index].mesh->triangles().size(), Vector3r::Zero());
      f[triangle] += force;
    };
    const int bodyCount = static_cast<int>(model_.bodies.size());
    for (size_t k = 0; k < data_.pairContacts.size(); ++k)
      for (const TriangleContact& c : data_.pairContacts[k]) {
        // c.load.force along n12 and c.friction.force act on the other side; the body receives the opposite.
        const Vector3r onOther = c.load.force * c.normal + c.friction.force;
        add(data_.pairs[k].body, c.geom.triangle, -onOther);
        if (c.geom.partnerTriangle >= 0 && data_.pairs[k].other < bodyCount)
          add(data_.pairs[k].other, c.geom.partnerTriangle, onOther);
      }
    bp::dict d;
    for (const auto& [index, f] : forces) d[model_.bodies[index].id] = toArray(f);
    return d;
  }

  bool keepTriangleContacts() const { return data_.keepTriangleContacts; }
  void setKeepTriangleContacts(bool keep) { data_.keepTriangleContacts = keep; }

  bp::dict statistics() const {
    const ContactStatistics& c = data_.statistics;
    bp::dict s;
    s["body_pairs"] = c.bodyPairs;
    s["touching_pairs"] = c.touchingPairs;
    s["candidates"] = c.narrowPhase.candidates;
    s["rejected_not_facing"] = c.narrowPhase.notFacing;
    s["rejected_no_overlap"] = c.narrowPhase.noOverlap;
    s["rejected_outside_circle"] = c.narrowPhase.outsideCircle;
    s["rejected_empty_polygon"] = c.narrowPhase.emptyPolygon;
    s["rejected_beyond_contact_circle"] = c.narrowPhase.beyondContactCircle;
    s["rejected_through_body"] = c.narrowPhase.throughBody;
    s["quadrature_contacts"] = c.quadratureContacts;
    s["direct_contacts"] = c.directContacts;
    s["sphere_contacts"] = c.sphereContacts;
    s["sliding_contacts"] = c.slidingContacts;
    s["neighbour_rebuilds"] = c.neighbourRebuilds;
    s["candidate_rebuilds"] = c.candidateRebuilds;
    s["near_rebuilds"] = c.nearRebuilds;
    s["broad_phase_ms"] = 1e3 * data_.times.broadPhase;
    s["pairs_ms"] = 1e3 * data_.times.pairs;
    s["reduction_ms"] = 1e3 * data_.times.reduction;
    s["read_ms"] = readMs_;
    s["write_ms"] = writeMs_;
    return s;
  }

 private:
  // YADE's id of an engine index (bodies, then partners).
  int yadeId(int index) const {
    const int bodyCount = static_cast<int>(model_.bodies.size());
    return index < bodyCount ? model_.bodies[index].id : model_.partners[index - bodyCount].id;
  }

  ContactModel model_;
  ContactData data_;
  FastBody fastest_;
  Real readMs_ = 0, writeMs_ = 0;  // the bridge's share of the last step: states in, wrenches out
};

void requireFinite(const Vector3r& v, const char* name) {
  if (!v.allFinite()) throw std::invalid_argument(std::string(name) + " must be finite");
}

Quaternionr rotation(const Quaternionr& q, const char* name) {
  if (!q.coeffs().allFinite() || q.norm() == 0) throw std::invalid_argument(std::string(name) + " must be a finite rotation");
  return q.normalized();
}

BodyState bodyState(const Vector3r& pos, const Quaternionr& ori, const Vector3r& vel, const Vector3r& angVel,
                    int index) {
  const std::string suffix = index ? std::to_string(index) : "";
  requireFinite(pos, ("pos" + suffix).c_str());
  requireFinite(vel, ("vel" + suffix).c_str());
  requireFinite(angVel, ("ang_vel" + suffix).c_str());
  return {pos, rotation(ori, ("ori" + suffix).c_str()), vel, angVel};
}

bp::dict describe(const TriangleContact& c) {
  bp::dict d;
  d["triangle1"] = c.geom.triangle;
  d["triangle2"] = c.geom.partnerTriangle;
  d["sphere_overlap"] = c.geom.sphereOverlap;
  d["effective_overlap"] = c.geom.effectiveOverlap;
  d["radius"] = c.geom.radius;
  d["contact_radius"] = c.geom.contactRadius;
  d["point"] = c.point;
  d["normal"] = c.normal;
  d["regime"] = c.load.regime == Regime::Direct ? "direct" : "quadrature";
  d["normal_force"] = c.load.force;
  d["tangential_force"] = c.friction.force;
  d["sliding"] = c.friction.sliding;
  d["node_forces1"] = bp::make_tuple(c.nodeForces[0], c.nodeForces[1], c.nodeForces[2]);
  if (c.geom.partnerTriangle >= 0)
    d["node_forces2"] = bp::make_tuple(c.partnerNodeForces[0], c.partnerNodeForces[1], c.partnerNodeForces[2]);
  return d;
}

bp::list describeAll(const std::vector<TriangleContact>& contacts) {
  bp::list listed;
  for (const TriangleContact& c : contacts) listed.append(describe(c));
  return listed;
}

bp::tuple asTuple(const PairEvaluation& e) {
  return bp::make_tuple(e.onFirst.force, e.onFirst.torque, e.onSecond.force, e.onSecond.torque, describeAll(e.contacts));
}

bp::tuple planeContact(const BodyMesh& mesh, const Vector3r& pos, const Quaternionr& ori, const Vector3r& planePoint,
                       const Vector3r& planeNormal, const HertzMaterial& meshMaterial,
                       const HertzMaterial& planeMaterial, const Vector3r& vel, const Vector3r& angVel, Real gamma,
                       const std::string& regime, const std::string& friction, const std::string& curvature) {
  requireFinite(planePoint, "plane_point");
  requireFinite(planeNormal, "plane_normal");
  if (planeNormal.norm() == 0) throw std::invalid_argument("plane_normal must not be zero");
  const PairEvaluation e = roundedmesh::planeContact(roundedBody(0, mesh, meshMaterial), bodyState(pos, ori, vel, angVel, 0),
                                                     Plane{planePoint, planeNormal.normalized()}, planeMaterial,
                                                     pressureOptions(gamma, regime, curvature), false,
                                                     frictionLaw(friction));
  return bp::make_tuple(e.onFirst.force, e.onFirst.torque);
}

bp::tuple sphereContact(const BodyMesh& mesh, const Vector3r& pos, const Quaternionr& ori, const Vector3r& centre,
                        Real radius, const HertzMaterial& meshMaterial, const HertzMaterial& sphereMaterial,
                        const Vector3r& vel, const Vector3r& angVel, const Vector3r& sphereVel,
                        const Vector3r& sphereAngVel, Real gamma, const std::string& regime, bool details,
                        const std::string& friction, const std::string& curvature) {
  requireFinite(centre, "centre");
  if (!(std::isfinite(radius) && radius > 0))
    throw std::invalid_argument("radius must be positive and finite, got " + std::to_string(radius));
  return asTuple(roundedmesh::sphereContact(roundedBody(0, mesh, meshMaterial), bodyState(pos, ori, vel, angVel, 0),
                                            Sphere{radius},
                                            bodyState(centre, Quaternionr::Identity(), sphereVel, sphereAngVel, 2),
                                            sphereMaterial, pressureOptions(gamma, regime, curvature), details,
                                            frictionLaw(friction)));
}

bp::tuple partnerContact(const BodyMesh& mesh, const Vector3r& pos, const Quaternionr& ori, const bp::object& partner,
                         const HertzMaterial& meshMaterial, const HertzMaterial& partnerMaterial, const Vector3r& vel,
                         const Vector3r& angVel, Real gamma, const std::string& regime, bool details,
                         const std::string& friction, const std::string& curvature) {
  const int id = bp::extract<int>(partner.attr("id"));
  const PartnerShape shape = yadeShape(partner, id);
  const bp::object s = partner.attr("state");
  BodyState partnerState;
  partnerState.position = bp::extract<Vector3r>(s.attr("pos"));
  partnerState.orientation = bp::extract<Quaternionr>(s.attr("ori"));
  partnerState.velocity = bp::extract<Vector3r>(s.attr("vel"));
  partnerState.angularVelocity = bp::extract<Vector3r>(s.attr("angVel"));
  if (!(partnerState.position.allFinite() && partnerState.orientation.coeffs().allFinite() &&
        partnerState.orientation.norm() > 0 && partnerState.velocity.allFinite() &&
        partnerState.angularVelocity.allFinite()))
    throw std::invalid_argument("partner (body " + std::to_string(id) +
                                "): its state (pos, ori, vel, angVel) must be finite, with a nonzero ori");
  partnerState.orientation.normalize();
  return asTuple(roundedmesh::partnerContact(roundedBody(0, mesh, meshMaterial), bodyState(pos, ori, vel, angVel, 0),
                                             shape, partnerState, partnerMaterial,
                                             pressureOptions(gamma, regime, curvature), details, frictionLaw(friction)));
}

bp::tuple bodyContact(const BodyMesh& mesh1, const Vector3r& pos1, const Quaternionr& ori1, const BodyMesh& mesh2,
                      const Vector3r& pos2, const Quaternionr& ori2, const HertzMaterial& material1,
                      const HertzMaterial& material2, const Vector3r& vel1, const Vector3r& angVel1,
                      const Vector3r& vel2, const Vector3r& angVel2, Real gamma, const std::string& regime,
                      bool details, const std::string& friction, const std::string& curvature) {
  return asTuple(roundedmesh::bodyContact(roundedBody(0, mesh1, material1), bodyState(pos1, ori1, vel1, angVel1, 1),
                                          roundedBody(1, mesh2, material2), bodyState(pos2, ori2, vel2, angVel2, 2),
                                          pressureOptions(gamma, regime, curvature), details, frictionLaw(friction)));
}

const char* partnerKindName(const Plane&) { return "Plane"; }
const char* partnerKindName(const Wall&) { return "Wall"; }
const char* partnerKindName(const Box&) { return "Box"; }
const char* partnerKindName(const Facet&) { return "Facet"; }
const char* partnerKindName(const Sphere&) { return "Sphere"; }

}  // namespace

void exposeEngine() {
  bp::class_<Engine, boost::noncopyable>("Engine", "Contact engine state of one scene (used by roundedmesh.scene).")
      .def("add_body", &Engine::addBody, (bp::arg("id"), bp::arg("mesh"), bp::arg("material")))
      .def("add_partner", &Engine::addPartner, (bp::arg("body"), bp::arg("material")))
      .def("add_sphere", &Engine::addSphere, (bp::arg("body"), bp::arg("material")))
      .def("set_options", &Engine::setOptions,
           (bp::arg("gamma"), bp::arg("regime"), bp::arg("friction"), bp::arg("stop_overlap"), bp::arg("curvature")))
      .def("step", &Engine::step, bp::arg("O"))
      .def("stops", &Engine::stops)
      .def("fastest", &Engine::fastest)
      .def("stability_limit", &Engine::stabilityLimit,
           (bp::arg("body_masses"), bp::arg("partner_masses"), bp::arg("body_inertias"), bp::arg("partner_inertias"),
            bp::arg("impact_speed") = 0.0))
      .def("springs", &Engine::springs)
      .def("restore_springs", &Engine::restoreSprings, bp::arg("record"))
      .add_property("statistics", &Engine::statistics)
      .def("contacts", &Engine::contacts)
      .def("energy", &Engine::energy)
      .def("triangle_forces", &Engine::triangleForces)
      .add_property("keep_triangle_contacts", &Engine::keepTriangleContacts, &Engine::setKeepTriangleContacts);

  // The engine's constants, declared once in pkg/engine/ContactModel.hpp.
  bp::scope().attr("STOP_OVERLAP") = kStopOverlap;
  bp::scope().attr("DEEPEST_OVERLAP") = kDeepestOverlap;
  bp::def("partner_kind", +[](const bp::object& body) {
            const int id = bp::extract<int>(body.attr("id"));
            return std::visit([](const auto& shape) { return partnerKindName(shape); }, yadeShape(body, id));
          }, bp::arg("body"),
          "'Wall', 'Box', 'Facet' or 'Sphere' for a body that can be a contact partner; ValueError otherwise.");

  bp::def("plane_contact", &planeContact,
          (bp::arg("mesh"), bp::arg("pos"), bp::arg("ori"), bp::arg("plane_point"), bp::arg("plane_normal"),
           bp::arg("mesh_material"), bp::arg("plane_material"), bp::arg("vel") = Vector3r(Vector3r::Zero()),
           bp::arg("ang_vel") = Vector3r(Vector3r::Zero()), bp::arg("gamma") = 10.0, bp::arg("regime") = "auto",
           bp::arg("friction") = "spring", bp::arg("curvature") = "mean"),
          "(force, torque) on a rounded body at pos, ori, moving with vel, ang_vel, pressed against the fixed\n"
          "plane through plane_point with plane_normal pointing toward the body side. Torque is about pos.\n"
          "gamma and regime ('auto', 'quadrature', 'direct') select the pressure integration (Eq. 14); friction\n"
          "('spring', 'viscous') the tangential law and curvature ('mean', 'principal') the contact's curvature, as\n"
          "for rm.engine: the spring of a contact evaluated once has no history, so only its damping acts.");

  const Vector3r zero = Vector3r::Zero();
  bp::def("_sphere_contact", &sphereContact,
          (bp::arg("mesh"), bp::arg("pos"), bp::arg("ori"), bp::arg("centre"), bp::arg("radius"),
           bp::arg("mesh_material"), bp::arg("sphere_material"), bp::arg("vel") = zero, bp::arg("ang_vel") = zero,
           bp::arg("sphere_vel") = zero, bp::arg("sphere_ang_vel") = zero, bp::arg("gamma") = 10.0,
           bp::arg("regime") = "auto", bp::arg("details") = false, bp::arg("friction") = "spring",
           bp::arg("curvature") = "mean"),
          "(F1, T1, F2, T2, contacts): see roundedmesh.sphere_contact.");
  bp::def("_partner_contact", &partnerContact,
          (bp::arg("mesh"), bp::arg("pos"), bp::arg("ori"), bp::arg("partner"), bp::arg("mesh_material"),
           bp::arg("partner_material"), bp::arg("vel") = zero, bp::arg("ang_vel") = zero, bp::arg("gamma") = 10.0,
           bp::arg("regime") = "auto", bp::arg("details") = false, bp::arg("friction") = "spring",
           bp::arg("curvature") = "mean"),
          "(F1, T1, F2, T2, contacts): see roundedmesh.partner_contact.");
  bp::def("_body_contact", &bodyContact,
          (bp::arg("mesh1"), bp::arg("pos1"), bp::arg("ori1"), bp::arg("mesh2"), bp::arg("pos2"), bp::arg("ori2"),
           bp::arg("material1"), bp::arg("material2"), bp::arg("vel1") = zero, bp::arg("ang_vel1") = zero,
           bp::arg("vel2") = zero, bp::arg("ang_vel2") = zero, bp::arg("gamma") = 10.0, bp::arg("regime") = "auto",
           bp::arg("details") = false, bp::arg("friction") = "spring", bp::arg("curvature") = "mean"),
          "(F1, T1, F2, T2, contacts): see roundedmesh.body_contact.");
}

}  // namespace roundedmesh::python
