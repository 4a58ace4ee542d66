// What a test measures of a mode, one unit per kind of quantity (issue 22):
// each owns its residual rows and their derivatives, what the test would
// measure of a model mode, its noise, and the names of its rows. identify,
// diagnose, the starts, the experiment advice and the synthetic generator
// all go through Measurements(). Adding a quantity that identify fits is its
// fields in MeasuredMode, one file (datasets/measurement_*.cc) and a line in
// Measurements() (datasets/measurement.cc).
#ifndef RINGID_DATASETS_MEASUREMENT_H_
#define RINGID_DATASETS_MEASUREMENT_H_

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "datasets/dataset.h"
#include "datasets/measurement_options.h"
#include "model/modal.h"

namespace ringid {

enum class Quantity { kFrequency, kDamping, kShape };
template <>
struct EnumNames<Quantity> {
  static constexpr std::array<const char*, 3> kNames = {"frequency", "damping", "shape"};
};

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

class Measurement {
 public:
  virtual ~Measurement() = default;
  virtual Quantity quantity() const = 0;
  // What it is in words, as experiment advice names it ("mode shape").
  virtual const char* description() const = 0;
  // Whether measured mode m carries it.
  virtual bool In(const MeasuredMode& m) const = 0;
  // Its residual rows for m: 0 where m lacks it or `o` leaves it out.
  virtual int Rows(const MeasuredMode& m, const MeasurementOptions& o) const = 0;
  // (model - measured) / sigma against model mode `mode` into r[0, Rows).
  // With `params`, dr(row, p) = d r / d (catalogue parameter p) for each p
  // listed (the mode carries derivatives).
  virtual void Evaluate(const MeasuredMode& m, const Mode& mode, const MeasurementOptions& o,
                        double* r, const std::vector<int>* params,
                        Eigen::Ref<RowMatrix> dr) const = 0;
  // A row's measured value and sigma, for a quantity of one row that a log
  // misfit describes (estimation/starts.cc); false for the others.
  virtual bool Scalar(const MeasuredMode& m, const MeasurementOptions& o, double* value,
                      double* sigma) const {
    return false;
  }
  // Sets what m carries of it to what the test measures of `mode`, without
  // noise; m's sigmas are kept.
  virtual void Measure(const Mode& mode, const MeasurementOptions& o, MeasuredMode* m) const = 0;
  // Gives m (which lacks it) what the test could add: `mode`'s value with
  // standard error `sigma` (every component of its plane for a shape).
  virtual void Add(const Mode& mode, const MeasurementOptions& o, double sigma,
                   MeasuredMode* m) const = 0;
  // Noise of level `noise` on a noise-free value m carries (relative for a
  // frequency or damping ratio, absolute for shape components), its sigma
  // set to match; draw() gives N(0, 1). Nothing where m lacks it.
  virtual void AddNoise(double noise, const std::function<double()>& draw,
                        MeasuredMode* m) const = 0;
};

// Every quantity, in the order of a measured mode's rows.
const std::vector<const Measurement*>& Measurements();
const Measurement& MeasurementOf(Quantity q);

// The standard deviation a measured frequency is weighted by (Hz).
double FrequencySigma(const MeasuredMode& m, const MeasurementOptions& o);

// The model's real shape under a convention, as measured shapes are made
// (docs/conventions.md §2: the largest component's phase removed).
RealShapeVector ComparableShape(const Mode& mode, ShapeConvention convention);
// The same for comparison with `measured`, and its derivative with respect to
// catalogue parameter p (the mode must carry derivatives). Under the
// contract's convention the phase removed is that of the measured shape's
// largest component, the one the convention made real when it was measured,
// unless the model's magnitude there is below kShapeReferenceShare of its
// largest or the model's largest component is not measured (then the
// measured shape's reference was not measured either: ShapeReference). The
// model's own largest component would flip the real part wherever two of
// its components tie: a step in the residuals at which every fit stalls.
RealShapeVector ComparableShape(const Mode& mode, ShapeConvention convention,
                                const std::vector<std::pair<Dof, double>>& measured);
RealShapeVector ComparableShapeDerivative(const Mode& mode, ShapeConvention convention,
                                          const std::vector<std::pair<Dof, double>>& measured,
                                          int p);
inline constexpr double kShapeReferenceShare = 0.5;
int ShapeReference(const Mode& mode, const std::vector<std::pair<Dof, double>>& measured);
// MAC of a real model shape against a measured shape on its components.
double Mac(const RealShapeVector& model,
           const std::vector<std::pair<Dof, double>>& measured);

}  // namespace ringid

#endif  // RINGID_DATASETS_MEASUREMENT_H_
