// Every option of the contact engine in one struct (rm.engine(...), rm.EngineOptions): the normal law and its
// integration (PressureOptions, law/), the friction law, the stop rule's overlap, the deep-overlap core's inset and the
// threads of a step. The
// field table below is the one description of each option: its name as users write it, its meaning, its allowed
// values; validate() holds the rules on single fields and between fields. The Python binding, the scene's saved
// record and the docs are made from it.
#pragma once

#include <string>
#include <vector>

#include "pkg/law/Law2_PressureGeom_HertzPhys_IntegratedPressure.hpp"
#include "pkg/law/TangentialSpring.hpp"

namespace roundedmesh {

// The overlap, as a fraction of the smaller side's size (volume-equivalent radius, or a sphere's radius), past which
// a growing overlap stops the run (StopRules.hpp): the depth to which two bodies' contact force is measured
// (doc/validation.md, "Deep overlaps"). A body resting under its weight overlaps about 0.01.
constexpr Real kStopOverlap = 0.5;

// How far below the surface each sphere of a body's core lies, as a fraction of that inscribed sphere's radius
// (CoreRepulsion.hpp): two cores meet where a pair overlaps by this fraction of the sum of the inscribed radii there, past
// the Hertz range of those radii; 1: no core.
constexpr Real kCoreInset = 0.25;

// What a step measures of its own cost besides the wall time of its stages (ContactData's StageTimes): `Stages` also
// the CPU time inside the pairs, stage by stage (PairStageTimes), at about 24 ns per clock reading, a few per pair.
enum class Timing { Off, Stages };

struct EngineOptions {
  PressureOptions pressure;                     // gamma, regime, curvature, normal
  FrictionLaw friction = FrictionLaw::Spring;   // the tangential law of every pair (doc/physics.md, "Friction")
  Real stopOverlap = kStopOverlap;              // infinite: no overlap stops a run (StopRules.hpp)
  Real coreInset = kCoreInset;                  // the deep-overlap term's onset (CoreRepulsion.hpp); 1: none
  // OpenMP threads of a step; 0: YADE's convention, OMP_NUM_THREADS where set (yade -jN sets it), else one.
  int threads = 0;
  Timing timing = Timing::Off;

  // Throws std::invalid_argument naming the option (as users write it) and the rule it breaks.
  void validate() const;
  // The threads a step runs on (0 resolved as above). The step's parallel regions name this count (num_threads)
  // and leave the calling thread's OpenMP default alone: YADE sizes a scene's per-thread force buffers by that
  // default when it makes the scene (O.load), and its own loops run on it, so changing it crashes YADE's engines.
  int resolvedThreads() const;

  bool operator==(const EngineOptions& o) const;
  bool operator!=(const EngineOptions& o) const { return !(*this == o); }
};

// One option of the field table. A choice lists its allowed values' names (the enum's values in order); a number
// has none.
struct EngineOptionField {
  const char* name;                  // as users write it: rm.engine(name=...)
  const char* meaning;               // one line, for docstrings and messages
  std::vector<const char*> choices;  // empty for a number
};

const std::vector<EngineOptionField>& engineOptionFields();
// The field named `name`; nullptr if there is none.
const EngineOptionField* findEngineOptionField(const std::string& name);
// The fields' names, comma-separated, for messages.
std::string engineOptionNames();

// A choice's value by name and back, for the option `name` of the table; numbers as numbers. Throws
// std::invalid_argument naming the option and its allowed values.
std::string choiceName(const EngineOptions& options, const std::string& name);
void setChoice(EngineOptions& options, const std::string& name, const std::string& value);
Real numberValue(const EngineOptions& options, const std::string& name);
void setNumber(EngineOptions& options, const std::string& name, Real value);

}  // namespace roundedmesh
