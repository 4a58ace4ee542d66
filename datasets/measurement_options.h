// How measured quantities are weighted and compared with the model's
// (ResidualOptions extends it with what only a fit needs).
#ifndef RINGID_DATASETS_MEASUREMENT_OPTIONS_H_
#define RINGID_DATASETS_MEASUREMENT_OPTIONS_H_

#include <array>
#include <limits>

#include "model/enum_names.h"

namespace ringid {

// How a measured frequency's residual is weighted.
enum class FrequencyWeighting {
  kSigma,     // 1 / frequency_sigma_hz (relative_sigma * f where absent)
  kRelative,  // 1 / (relative_sigma * f): eqs. (19)-(20) up to a constant
};
template <>
struct EnumNames<FrequencyWeighting> {
  static constexpr std::array<const char*, 2> kNames = {"sigma", "relative"};
};

// How a measured real shape was made from a complex eigenvector.
enum class ShapeConvention {
  kContract,  // docs/conventions.md §2: largest displacement real, real part
  kPaper,     // the paper's Tables 4-5 (Mode::PaperShape)
};
template <>
struct EnumNames<ShapeConvention> {
  static constexpr std::array<const char*, 2> kNames = {"contract", "paper"};
};

struct MeasurementOptions {
  FrequencyWeighting frequency_weighting = FrequencyWeighting::kSigma;
  // Relative frequency standard error used where no sigma is given.
  double relative_sigma = 0.01;
  // Damping and shape residuals are used where the dataset gives them.
  bool use_damping = true;
  bool use_shapes = true;
  double default_damping_sigma = 0.02;  // where damping_sigma is absent
  double default_shape_sigma = 0.05;    // where shape_sigma is absent
  ShapeConvention shape_convention = ShapeConvention::kContract;
  // The lines of measured FRFs fitted: those within [low, high] Hz (all by
  // default; docs/conventions.md §9 says why and when to narrow it).
  double band_low_hz = 0;
  double band_high_hz = std::numeric_limits<double>::infinity();
};

}  // namespace ringid

#endif  // RINGID_DATASETS_MEASUREMENT_OPTIONS_H_
