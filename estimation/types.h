// The option and result enums of estimation (those of the measurements in
// datasets/measurement_options.h, included here), each with its names (ToString /
// FromString, model/enum_names.h), and the small value types options hold.
#ifndef RINGID_ESTIMATION_TYPES_H_
#define RINGID_ESTIMATION_TYPES_H_

#include <array>
#include <map>
#include <string>

#include "datasets/measurement_options.h"  // FrequencyWeighting, ShapeConvention
#include "model/enum_names.h"
#include "model/parameters.h"

namespace ringid {

// How to fit.
enum class Method { kLevenbergMarquardt, kSimplex };
template <>
struct EnumNames<Method> {
  static constexpr std::array<const char*, 2> kNames = {"lm", "simplex"};
};

// Bounds a user sets on one parameter, in its units; they replace the box of
// bound_factor for every coordinate of the parameter.
struct Bound {
  double lower = 0, upper = 0;
};
using Bounds = std::map<Param, Bound>;

// Which bound a fitted coordinate sits on.
enum class BoundSide { kLower, kUpper };
template <>
struct EnumNames<BoundSide> {
  static constexpr std::array<const char*, 2> kNames = {"lower", "upper"};
};

// How the Jacobians of the residuals are made.
enum class Derivatives {
  kNumeric,   // central differences through the eigen-solution
  kAnalytic,  // eigenvalue and eigenvector derivatives (docs/model.md §15),
              // central differences where two eigenvalues coincide
  kAuto,      // per condition: analytic where it measures no modes (FRFs
              // and static stiffnesses, dH = -H dZ H: exact and cheaper),
              // numeric where it measures modes (the design's default)
};

template <>
struct EnumNames<Derivatives> {
  static constexpr std::array<const char*, 3> kNames = {"numeric", "analytic", "auto"};
};

// Whether identifiability computes profile intervals: each is a series of
// refits, so where one fit is costly (FRFs) only when asked.
enum class Profiles {
  kAuto,    // computed unless a condition measures FRFs
  kAlways,
  kNever,
};

template <>
struct EnumNames<Profiles> {
  static constexpr std::array<const char*, 3> kNames = {"auto", "always", "never"};
};

// Where a start of an identification came from.
// kEffectAtZero: diagnose's re-calibration of the baseline from an effect's
// fit that held the effect at 0 and beat the baseline.
enum class StartOrigin { kInitial, kFrequencyMatched, kScattered, kEffectAtZero };
template <>
struct EnumNames<StartOrigin> {
  static constexpr std::array<const char*, 4> kNames = {"initial", "frequency_matched",
                                                        "scattered", "effect_at_zero"};
};

// What the data determine of a parameter.
enum class Identifiability { kYes, kPracticallyNo, kNo };
template <>
struct EnumNames<Identifiability> {
  static constexpr std::array<const char*, 3> kNames = {"yes", "practically_no", "no"};
};

// A parameter, or its value in one condition: "NAME" or "NAME@CONDITION".
struct ParameterKey {
  Param param = Param::m_b;
  std::string condition;  // empty: shared by every condition

  std::string Text() const;
  static bool Parse(const std::string& text, ParameterKey* key);
  static constexpr char kKeyDescription[] =
      "parameter name, or NAME@CONDITION for a per-condition parameter of a format-2 dataset";
  bool operator==(const ParameterKey& o) const {
    return param == o.param && condition == o.condition;
  }
};

}  // namespace ringid

#endif  // RINGID_ESTIMATION_TYPES_H_
