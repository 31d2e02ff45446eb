// The contact step as the Python package drives it (roundedmesh/scene.py, pkg/engine/ContactStep.hpp), and
// plane_contact, partner_contact, sphere_contact and body_contact (pkg/engine/PairEvaluation.hpp): arguments
// checked and converted here.
#include <boost/python.hpp>

#include <chrono>
#include <cmath>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "pkg/engine/ContactStep.hpp"
#include "pkg/engine/PairEvaluation.hpp"
#include "pkg/io/SpringRecord.hpp"
#include "pkg/law/FacingRamp.hpp"
#include "pkg/meshing/BodyMesh.hpp"
#include "py/module/ExposeEngineOptions.hpp"
#include "py/module/NumpyConversion.hpp"
#include "py/module/YadeBridge.hpp"

namespace roundedmesh::python {
namespace {

bp::tuple asTuple(const StabilityLimit& limit, int bodyId, int otherId) {
  return bp::make_tuple(limit.timeStep, bodyId, otherId, limit.tangential);
}

// The contacts of one YADE scene (roundedmesh/scene.py builds one per revision of the scene's tags): its model,
// the data kept from step to step, and the step as YADE's PyRunner runs it.
class SceneContacts {
 public:
  void addBody(int id, const BodyMesh& mesh, const HertzMaterial& material) {
    model_.bodies.push_back(roundedBody(id, mesh, material));
  }
  // edgeRadius [m]: what its convex edges and corners are rounded by; negative: the default (edgeRadiusFor).
  void addPartner(const bp::object& body, const HertzMaterial& material, Real edgeRadius) {
    const int id = bp::extract<int>(body.attr("id"));
    model_.partners.push_back({id, yadeShape(body, id), material, false, edgeRadius});
  }
  // A Wall, Box or Facet partner that is not in this process under yade.mpy: its shape is read when it arrives
  // (readScene); until then it is a plane, for the time-step check alone.
  void addAbsentPartner(int id, const HertzMaterial& material, Real edgeRadius) {
    model_.partners.push_back({id, Plane{Vector3r::Zero(), Vector3r::UnitZ()}, material, false, edgeRadius});
  }
  // A sphere body (rm.add_sphere): a YADE Sphere whose contacts with every partner the engine computes too.
  void addSphere(const bp::object& body, const HertzMaterial& material) {
    const int id = bp::extract<int>(body.attr("id"));
    model_.partners.push_back({id, sphereShape(body, id), material, true});
  }
  void setOptions(const EngineOptions& options) {
    options.validate();
    model_.options = options;
    data_.checkedTimeStep = {};  // the limit depends on the friction law
  }
  const EngineOptions& options() const { return model_.options; }

  // One contact step on the current YADE scene (pkg/engine/ContactStep.hpp): the states in, the scene's springs
  // in if this engine did not write them, contactStep, and for a kept step the wrenches and springs out. Returns
  // the report as a dict (roundedmesh/scene.py, step): {'missing': [ids]} if managed bodies have left the scene
  // (nothing computed); else 'unstable' (None, or (limit [s], YADE id of the body, of the other, tangential)),
  // 'stops' [(cause 'crossed' or 'overlap', id, other id, overlap [m], size [m], point [m])], 'stop_speed' [m/s],
  // 'stop_time_step' [s], 'fastest' (id or -1, speed [m/s], fraction of its contact depth per step, that depth
  // [m], impact time step [s] or 0), 'deep_starts' [(id, other id, overlap [m], size [m])], 'energy' (elastic
  // [J], normal damping [W], friction [W]). rank: this process's once yade.mpy has split the scene (its pairs and
  // wrenches, YadeBridge.hpp, readScene), -1 in one process.
  bp::dict step(const bp::object& omega, int rank) {
    const auto start = std::chrono::steady_clock::now();
    bp::dict report;
    const std::vector<int> missing = readScene(omega, model_, data_, rank);
    if (!missing.empty()) {
      bp::list ids;
      for (int id : missing) ids.append(id);
      report["missing"] = ids;
      return report;
    }
    takeSprings(omega);
    const auto read = std::chrono::steady_clock::now();
    const StepReport r = contactStep(model_, data_);
    const auto computed = std::chrono::steady_clock::now();
    if (r.kept()) {
      applyWrenches(omega, model_, data_);
      keepSprings(omega);
      deepest_ = r.deepest;
    }
    readMs_ = std::chrono::duration<Real, std::milli>(read - start).count();
    writeMs_ = std::chrono::duration<Real, std::milli>(std::chrono::steady_clock::now() - computed).count();
    report["unstable"] = r.unstable ? asTuple(*r.unstable, yadeId(r.unstable->body), yadeId(r.unstable->other))
                                    : bp::object();
    bp::list stops;
    for (const StopReason& s : r.stops)
      stops.append(bp::make_tuple(s.cause == StopCause::CentreCrossed ? "crossed" : "overlap", yadeId(s.body),
                                  yadeId(s.other), s.overlap, s.size, s.point));
    report["stops"] = stops;
    report["stop_speed"] = r.stopSpeed;
    report["stop_time_step"] = r.stopTimeStep;
    const FastBody& f = r.fastest;
    report["fastest"] = bp::make_tuple(f.body < 0 ? -1 : yadeId(f.body), f.speed, f.fraction, f.depth,
                                       r.fastTimeStep);
    bp::list deep;
    for (const DeepPair& d : r.deepStarts) deep.append(bp::make_tuple(yadeId(d.body), yadeId(d.other), d.overlap, d.size));
    report["deep_starts"] = deep;
    report["energy"] = bp::make_tuple(r.energy.elastic, r.energy.dampingPower, r.energy.frictionPower);
    return report;
  }

  // (time step [s], YADE id of the body, YADE id of the other body, whether the limit is the tangential
  // contact's) of the most restrictive pair, for the masses and principal moments of inertia the bodies have in
  // YADE now (one that has left the scene puts no limit). With impactSpeed [m/s] > 0, also the step that resolves an impact at that speed (impactTimeStep).
  bp::tuple stabilityLimit(const bp::object& omega, Real impactSpeed) {
    readScene(omega, model_, data_);  // a body that has left the scene puts no limit
    const StabilityLimit limit = roundedmesh::stabilityLimit(model_, data_.bodyMasses, data_.partnerMasses,
                                                             data_.bodyInertias, data_.partnerInertias, impactSpeed);
    if (limit.body < 0) return asTuple(limit, -1, -1);
    return asTuple(limit, yadeId(limit.body), yadeId(limit.other));
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
    s["exact_contacts"] = c.exactContacts;
    s["sphere_contacts"] = c.sphereContacts;
    s["core_contacts"] = c.coreContacts;
    s["sliding_contacts"] = c.slidingContacts;
    s["neighbour_rebuilds"] = c.neighbourRebuilds;
    s["candidate_rebuilds"] = c.candidateRebuilds;
    s["near_rebuilds"] = c.nearRebuilds;
    s["near_pairs_scanned"] = c.nearPairsScanned;
    s["broad_phase_ms"] = 1e3 * data_.times.broadPhase;
    s["pairs_ms"] = 1e3 * data_.times.pairs;
    s["reduction_ms"] = 1e3 * data_.times.reduction;
    s["lists_cpu_ms"] = 1e3 * c.cpu.lists;
    s["near_search_cpu_ms"] = 1e3 * c.cpu.nearSearch;
    s["narrow_phase_cpu_ms"] = 1e3 * c.cpu.narrowPhase;
    s["law_cpu_ms"] = 1e3 * c.cpu.law;
    s["core_cpu_ms"] = 1e3 * c.cpu.core;
    s["read_ms"] = readMs_;
    s["write_ms"] = writeMs_;
    s["deepest_pair_overlap"] = deepest_.overlap;
    s["deepest_pair_fraction"] = deepest_.overlap / deepest_.size;
    s["threads"] = model_.options.resolvedThreads();
    return s;
  }

 private:
  // YADE's id of an engine index (bodies, then partners).
  int yadeId(int index) const {
    const int bodyCount = static_cast<int>(model_.bodies.size());
    return index < bodyCount ? model_.bodies[index].id : model_.partners[index - bodyCount].id;
  }

  // Before a step: the scene's springs (O.tags[kSpringsTag], "token:record"), unless this engine wrote them
  // itself (same token): a loaded scene, or one whose springs another engine state wrote. Pairs whose bodies the
  // engine does not know (erased since) are dropped.
  void takeSprings(const bp::object& omega) {
    const std::string tagged = readTag(omega, kSpringsTag);
    const size_t colon = tagged.find(':');
    const std::string token = tagged.substr(0, colon);
    if (token == springToken_) return;
    std::vector<std::pair<BodyPair, TangentialSpring>> springs;
    if (!token.empty()) {
      std::vector<SpringEntry> entries;
      try {
        entries = decodeSprings(colon == std::string::npos ? std::string() : tagged.substr(colon + 1));
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("the scene's tangential springs (O.tags['") + kSpringsTag +
                                    "']) are damaged: " + e.what());
      }
      std::map<int, int> index;
      for (size_t b = 0; b < model_.bodies.size(); ++b) index[model_.bodies[b].id] = static_cast<int>(b);
      for (size_t p = 0; p < model_.partners.size(); ++p)
        index[model_.partners[p].id] = static_cast<int>(model_.bodies.size() + p);
      for (const SpringEntry& e : entries) {
        const auto first = index.find(e.id1), second = index.find(e.id2);
        if (first != index.end() && second != index.end())
          springs.push_back({{first->second, second->second}, e.spring});
      }
    }
    data_.restoreSprings(std::move(springs));
    springToken_ = token;
  }

  // After a kept step: the engine's springs into the scene, so that O.save keeps them: "token:record", a token
  // unique to this write (the process's, and a count); "" when there are none and were none.
  void keepSprings(const bp::object& omega) {
    const auto active = data_.activeSprings();
    if (active.empty() && springToken_.empty()) return;
    std::vector<SpringEntry> entries;
    entries.reserve(active.size());
    for (const auto& [pair, spring] : active) entries.push_back({yadeId(pair.body), yadeId(pair.other), spring});
    springToken_ = active.empty() ? std::string() : processToken() + "." + std::to_string(++springWrites_);
    omega.attr("tags")[kSpringsTag] = active.empty() ? std::string() : springToken_ + ":" + encodeSprings(entries);
  }

  static const std::string& processToken() {
    static const std::string token = [] {
      std::random_device random;
      std::ostringstream s;
      s << std::hex << random() << random();
      return s.str();
    }();
    return token;
  }

  static std::string readTag(const bp::object& omega, const char* key) {
    const bp::object tags = omega.attr("tags");
    if (!bp::extract<bool>(tags.attr("has_key")(key))()) return std::string();
    return bp::extract<std::string>(tags[key]);
  }

  static constexpr const char* kSpringsTag = "roundedmesh.springs";
  ContactModel model_;
  ContactData data_;
  std::string springToken_;  // the token of the springs the engine holds; "": none
  static inline long springWrites_ = 0;
  Real readMs_ = 0, writeMs_ = 0;  // the bridge's share of the last step: states in, wrenches out
  DeepPair deepest_{-1, -1, 0, 1};  // of the last kept step
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
  d["regime"] = c.load.regime == Regime::Direct ? "direct" : c.load.regime == Regime::Exact ? "exact" : "quadrature";
  d["normal_force"] = c.load.force;
  d["elastic_energy"] = c.load.elasticEnergy;
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
                       const HertzMaterial& planeMaterial, const Vector3r& vel, const Vector3r& angVel, const EngineOptions& options) {
  requireFinite(planePoint, "plane_point");
  requireFinite(planeNormal, "plane_normal");
  if (planeNormal.norm() == 0) throw std::invalid_argument("plane_normal must not be zero");
  const PairEvaluation e = roundedmesh::planeContact(roundedBody(0, mesh, meshMaterial), bodyState(pos, ori, vel, angVel, 0),
                                                     Plane{planePoint, planeNormal.normalized()}, planeMaterial,
                                                     options);
  return bp::make_tuple(e.onFirst.force, e.onFirst.torque);
}

bp::tuple sphereContact(const BodyMesh& mesh, const Vector3r& pos, const Quaternionr& ori, const Vector3r& centre,
                        Real radius, const HertzMaterial& meshMaterial, const HertzMaterial& sphereMaterial,
                        const Vector3r& vel, const Vector3r& angVel, const Vector3r& sphereVel,
                        const Vector3r& sphereAngVel, bool details, const EngineOptions& options) {
  requireFinite(centre, "centre");
  if (!(std::isfinite(radius) && radius > 0))
    throw std::invalid_argument("radius must be positive and finite, got " + std::to_string(radius));
  return asTuple(roundedmesh::sphereContact(roundedBody(0, mesh, meshMaterial), bodyState(pos, ori, vel, angVel, 0),
                                            Sphere{radius},
                                            bodyState(centre, Quaternionr::Identity(), sphereVel, sphereAngVel, 2),
                                            sphereMaterial, options, details));
}

// A partner's state as YADE has it, checked finite.
BodyState partnerState(const bp::object& partner, int id) {
  const bp::object s = partner.attr("state");
  BodyState state;
  state.position = bp::extract<Vector3r>(s.attr("pos"));
  state.orientation = bp::extract<Quaternionr>(s.attr("ori"));
  state.velocity = bp::extract<Vector3r>(s.attr("vel"));
  state.angularVelocity = bp::extract<Vector3r>(s.attr("angVel"));
  if (!(state.position.allFinite() && state.orientation.coeffs().allFinite() && state.orientation.norm() > 0 &&
        state.velocity.allFinite() && state.angularVelocity.allFinite()))
    throw std::invalid_argument("partner (body " + std::to_string(id) +
                                "): its state (pos, ori, vel, angVel) must be finite, with a nonzero ori");
  state.orientation.normalize();
  return state;
}

// `partner`: one YADE Body, or a sequence of them (a surface: its Facets welded, as in a scene). For a sequence the
// third and fourth items list the wrench on each partner.
bp::tuple partnerContact(const BodyMesh& mesh, const Vector3r& pos, const Quaternionr& ori, const bp::object& partner,
                         const HertzMaterial& meshMaterial, const HertzMaterial& partnerMaterial, const Vector3r& vel,
                         const Vector3r& angVel, bool details, Real edgeRadius, const EngineOptions& options) {
  const RoundedBody body = roundedBody(0, mesh, meshMaterial);
  const BodyState state = bodyState(pos, ori, vel, angVel, 0);
  const bool one = PyObject_HasAttrString(partner.ptr(), "id");
  std::vector<Partner> partners;
  std::vector<BodyState> states;
  for (bp::stl_input_iterator<bp::object> it(one ? bp::object(bp::make_tuple(partner)) : partner), end; it != end; ++it) {
    const int id = bp::extract<int>((*it).attr("id"));
    partners.push_back({id, yadeShape(*it, id), partnerMaterial, false, edgeRadius});
    states.push_back(partnerState(*it, id));
  }
  if (partners.empty()) throw std::invalid_argument("partner: an empty sequence; give a body or a list of bodies");
  const PairEvaluation e = surfaceContact(body, state, partners, states, options, details);
  if (one) return asTuple(e);
  bp::list forces, torques;
  for (const Wrench& w : e.onPartners) {
    forces.append(w.force);
    torques.append(w.torque);
  }
  return bp::make_tuple(e.onFirst.force, e.onFirst.torque, forces, torques, describeAll(e.contacts));
}

bp::tuple bodyContact(const BodyMesh& mesh1, const Vector3r& pos1, const Quaternionr& ori1, const BodyMesh& mesh2,
                      const Vector3r& pos2, const Quaternionr& ori2, const HertzMaterial& material1,
                      const HertzMaterial& material2, const Vector3r& vel1, const Vector3r& angVel1,
                      const Vector3r& vel2, const Vector3r& angVel2, bool details, const EngineOptions& options) {
  return asTuple(roundedmesh::bodyContact(roundedBody(0, mesh1, material1), bodyState(pos1, ori1, vel1, angVel1, 1),
                                          roundedBody(1, mesh2, material2), bodyState(pos2, ori2, vel2, angVel2, 2),
                                          options, details));
}

const char* partnerKindName(const Plane&) { return "Plane"; }
const char* partnerKindName(const Wall&) { return "Wall"; }
const char* partnerKindName(const Box&) { return "Box"; }
const char* partnerKindName(const Facet&) { return "Facet"; }
const char* partnerKindName(const Sphere&) { return "Sphere"; }

}  // namespace

void exposeContactStep() {
  bp::class_<SceneContacts, boost::noncopyable>(
      "SceneContacts", "The contacts of one scene and its step (used by roundedmesh.scene).")
      .def("add_body", &SceneContacts::addBody, (bp::arg("id"), bp::arg("mesh"), bp::arg("material")))
      .def("add_partner", &SceneContacts::addPartner,
           (bp::arg("body"), bp::arg("material"), bp::arg("edge_radius") = -1.0))
      .def("add_absent_partner", &SceneContacts::addAbsentPartner,
           (bp::arg("id"), bp::arg("material"), bp::arg("edge_radius") = -1.0))
      .def("add_sphere", &SceneContacts::addSphere, (bp::arg("body"), bp::arg("material")))
      .def("set_options", &SceneContacts::setOptions, bp::arg("options"))
      .add_property("options", bp::make_function(&SceneContacts::options, bp::return_value_policy<bp::copy_const_reference>()))
      .def("step", &SceneContacts::step, (bp::arg("O"), bp::arg("rank") = -1))
      .def("stability_limit", &SceneContacts::stabilityLimit, (bp::arg("O"), bp::arg("impact_speed") = 0.0))
      .add_property("statistics", &SceneContacts::statistics)
      .def("contacts", &SceneContacts::contacts)
      .def("triangle_forces", &SceneContacts::triangleForces)
      .add_property("keep_triangle_contacts", &SceneContacts::keepTriangleContacts,
                    &SceneContacts::setKeepTriangleContacts);

  // The engine's constants, declared once in C++ (pkg/engine/EngineOptions.hpp, ContactModel.hpp, ContactStep.hpp,
  // pkg/law/FacingRamp.hpp).
  bp::scope().attr("STOP_OVERLAP") = kStopOverlap;
  bp::scope().attr("FACING_RAMP") = kFacingRamp;
  bp::scope().attr("DEEPEST_OVERLAP") = kDeepestOverlap;
  bp::scope().attr("FAST_STEP") = kFastStep;
  bp::def("partner_kind", +[](const bp::object& body) {
            const int id = bp::extract<int>(body.attr("id"));
            return std::visit([](const auto& shape) { return partnerKindName(shape); }, yadeShape(body, id));
          }, bp::arg("body"),
          "'Wall', 'Box', 'Facet' or 'Sphere' for a body that can be a contact partner; ValueError otherwise.");

  // One contact evaluated once (roundedmesh/contact.py gives them their defaults and documentation).
  bp::def("_plane_contact", &planeContact);
  bp::def("_sphere_contact", &sphereContact);
  bp::def("_partner_contact", &partnerContact);
  bp::def("_body_contact", &bodyContact);
}

}  // namespace roundedmesh::python
