// The engine's options (EngineOptions.hpp): the field table names every option once, with the allowed values of
// each choice in the order of its enum; validate() refuses a value out of range and the rule between fields, naming
// the option; the threads follow YADE's convention; and the normal laws' registry (NormalLaws.hpp) is the table's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include "pkg/engine/EngineOptions.hpp"
#include "pkg/law/NormalLaws.hpp"

namespace roundedmesh {
namespace {

std::string messageOf(const EngineOptions& options) {
  try {
    options.validate();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(EngineOptions, TheTableNamesEveryOptionOnceWithItsDefault) {
  std::string names;
  for (const EngineOptionField& f : engineOptionFields()) names += std::string(names.empty() ? "" : " ") + f.name;
  EXPECT_EQ(names, "gamma regime friction stop_overlap curvature normal core_inset threads timing");
  const EngineOptions defaults;
  EXPECT_EQ(numberValue(defaults, "gamma"), 10);  // the paper's
  EXPECT_EQ(choiceName(defaults, "regime"), "auto");
  EXPECT_EQ(choiceName(defaults, "friction"), "spring");
  EXPECT_EQ(numberValue(defaults, "stop_overlap"), kStopOverlap);
  EXPECT_EQ(choiceName(defaults, "curvature"), "mean");
  EXPECT_EQ(choiceName(defaults, "normal"), "pressure");
  EXPECT_EQ(numberValue(defaults, "core_inset"), kCoreInset);
  EXPECT_EQ(numberValue(defaults, "threads"), 0);
  EXPECT_EQ(choiceName(defaults, "timing"), "off");
  EXPECT_EQ(messageOf(defaults), "");
}

TEST(EngineOptions, ChoicesSetTheirEnumsByName) {
  EngineOptions o;
  setChoice(o, "regime", "exact");
  setChoice(o, "friction", "viscous");
  setChoice(o, "curvature", "principal");
  setChoice(o, "timing", "stages");
  EXPECT_EQ(o.timing, Timing::Stages);
  EXPECT_EQ(o.pressure.regime, RegimeChoice::Exact);
  EXPECT_EQ(o.friction, FrictionLaw::Viscous);
  EXPECT_EQ(o.pressure.curvature, CurvatureModel::Principal);
  setNumber(o, "gamma", 3);
  setNumber(o, "stop_overlap", std::numeric_limits<Real>::infinity());
  setNumber(o, "threads", 4);
  EXPECT_EQ(o.pressure.gamma, 3);
  EXPECT_TRUE(std::isinf(o.stopOverlap));
  EXPECT_EQ(o.threads, 4);
  EXPECT_NE(o, EngineOptions());
  try {
    setChoice(o, "friction", "dry");
    FAIL() << "an unknown friction law was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "friction must be 'spring' or 'viscous', got 'dry'");
  }
  EXPECT_THROW(setChoice(o, "gama", "x"), std::invalid_argument);
  EXPECT_THROW(setNumber(o, "regime", 1), std::invalid_argument);
  EXPECT_THROW(setNumber(o, "threads", 1.5), std::invalid_argument);
}

TEST(EngineOptions, ValidateNamesTheOptionAndTheRuleBetweenFields) {
  EngineOptions o;
  o.pressure.gamma = -1;
  EXPECT_NE(messageOf(o).find("gamma must be positive"), std::string::npos);
  o = EngineOptions();
  o.pressure.gamma = std::nan("");
  EXPECT_NE(messageOf(o).find("gamma"), std::string::npos);
  o = EngineOptions();
  o.stopOverlap = 0;
  EXPECT_NE(messageOf(o).find("stop_overlap must be positive"), std::string::npos);
  for (Real inset : {0.0, -0.1, 1.5, std::nan("")}) {
    o = EngineOptions();
    o.coreInset = inset;
    EXPECT_NE(messageOf(o).find("core_inset must be in (0, 1]"), std::string::npos) << inset;
  }
  o = EngineOptions();
  o.coreInset = 1;  // no core
  EXPECT_EQ(messageOf(o), "");
  o = EngineOptions();
  o.pressure.normal = NormalLaw::Energy;
  o.pressure.curvature = CurvatureModel::Principal;
  EXPECT_EQ(messageOf(o), "normal='energy' takes the contact circle of curvature='mean', not the ellipse of 'principal'");
}

TEST(EngineOptions, ThreadsFollowYadesConvention) {
  const char* saved = std::getenv("OMP_NUM_THREADS");
  const std::string previous = saved ? saved : "";
  EngineOptions o;
  unsetenv("OMP_NUM_THREADS");
  EXPECT_EQ(o.resolvedThreads(), 1);  // as `yade` without -j
  setenv("OMP_NUM_THREADS", "3", 1);  // as `yade -j3`
  EXPECT_EQ(o.resolvedThreads(), 3);
  o.threads = 2;  // the user's own choice wins
  EXPECT_EQ(o.resolvedThreads(), 2);
  if (saved) setenv("OMP_NUM_THREADS", previous.c_str(), 1); else unsetenv("OMP_NUM_THREADS");
}

// The registry of the normal laws is the table's choice, in the order of NormalLaw's values.
TEST(EngineOptions, NormalLawsAreTheRegistrys) {
  const EngineOptionField* normal = nullptr;
  for (const EngineOptionField& f : engineOptionFields())
    if (std::string(f.name) == "normal") normal = &f;
  ASSERT_NE(normal, nullptr);
  ASSERT_EQ(normal->choices.size(), normalLaws().size());
  for (size_t k = 0; k < normalLaws().size(); ++k) {
    EXPECT_STREQ(normal->choices[k], normalLaws()[k].name);
    EXPECT_EQ(static_cast<size_t>(normalLaws()[k].law), k);
    EXPECT_EQ(&normalLaw(normalLaws()[k].law), &normalLaws()[k]);
  }
}

}  // namespace
}  // namespace roundedmesh
