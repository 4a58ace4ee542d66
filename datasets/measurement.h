// What a test measures, as factors (issue 35): each kind of measurement owns
// its residual rows over one condition's parameters and their exact
// derivatives, what it needs of the model (the condition's paired modes, or
// a static solve), its noise model, its words in reports and advice, and its
// synthetic generator. identify, diagnose, the starts, identifiability's
// advice, the detectable sizes and the synthetic generator all go through
// Measurements(); none of them switches on the kind. The quantities of a
// measured mode (frequency, damping ratio, shape) are one family of
// ModeQuantity units; a static stiffness is another kind. Adding a kind is
// docs/development.md's steps: its fields in dataset.h and dataset_file.h,
// one file (datasets/measurement_*.cc) and a line in Measurements().
#ifndef RINGID_DATASETS_MEASUREMENT_H_
#define RINGID_DATASETS_MEASUREMENT_H_

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "datasets/dataset.h"
#include "datasets/measurement_options.h"
#include "model/modal.h"
#include "model/rigid_ring_model.h"

namespace ringid {

enum class Quantity { kFrequency, kDamping, kShape, kStatic, kFrf };
template <>
struct EnumNames<Quantity> {
  static constexpr std::array<const char*, 5> kNames = {"frequency", "damping", "shape",
                                                        "static", "frf"};
};

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// What the model gives one condition's measurements: its parameters and,
// for those of a mode, its solved modes and each measured mode's partner
// (pairs[i] for dataset mode i; without pairs, the model mode of its label).
struct ModelAt {
  const ModalModel* model = nullptr;
  const Parameters* parameters = nullptr;
  const ModalSolution* solution = nullptr;
  const std::vector<int>* pairs = nullptr;
  // The model mode measured mode i of `d` is compared with; null if none.
  const Mode* ModeOf(const Dataset& d, int i) const;
};

// Where a fit misses the data, per measured mode (datasets/measurement.h's
// kinds fill it, estimation/diagnose.h reports it).
struct ModeMisfit {
  std::optional<std::string> condition;  // formats 2, 3: the condition's name
  ModeLabel label;
  double chi2 = 0;                      // all its residuals, in sigma^2
  double frequency_sigma = 0;           // (model - measured) / sigma
  std::optional<double> damping_sigma;  // likewise
  double shape_chi2 = 0;
  std::string worst_component;          // the shape component furthest off
  double worst_component_sigma = 0;

  // "label", or "condition label" for format 2.
  std::string Name() const {
    return condition ? *condition + " " + LabelName(label) : std::string(LabelName(label));
  }

  template <class Archive>
  void Serialize(Archive* a) {
    a->VisitIfSet("condition", &condition);
    a->Visit("label", &label);
    a->Visit("chi2", &chi2);
    a->Visit("frequency_sigma", &frequency_sigma);
    a->Visit("damping_sigma", &damping_sigma);
    a->Visit("shape_chi2", &shape_chi2);
    a->Visit("worst_component", &worst_component);
    a->Visit("worst_component_sigma", &worst_component_sigma);
  }
};

// The same for an item of another kind: its residual in sigma, or for an
// item of many values (a frequency response function) their chi-square, their
// number and their rms as sigma.
struct ItemMisfit {
  std::optional<std::string> condition;  // formats 2, 3: the condition's name
  std::string name;                      // "static vertical stiffness", "FRF a/b"
  double sigma = 0;                      // (model - measured) / sigma; rms of many
  std::optional<double> chi2;            // of many values: their sum of squares
  std::optional<int> values;             // and their number

  template <class Archive>
  void Serialize(Archive* a) {
    a->VisitIfSet("condition", &condition);
    a->Visit("name", &name);
    a->Visit("sigma", &sigma);
    a->VisitIfSet("chi2", &chi2);
    a->VisitIfSet("values", &values);
  }
};
struct MisfitTable {
  std::vector<ModeMisfit> modes;  // one per measured mode, in dataset order
  std::vector<ItemMisfit> others;
};

// The standard errors experiment advice assumes of what a test could add.
struct AdviceSigmas {
  double frequency_relative = 0.01;  // a natural frequency, relative
  double damping = 0.02;          // a damping ratio, absolute
  double shape = 0.05;            // a shape component
  double static_relative = 0.02;  // a static stiffness, relative (contract §10)
};

// Where the items of the kinds come from: measured modes and static
// stiffnesses, each a record of the dataset in one condition. A condition's
// rows are its records' in this order, each record's kinds in the order of
// Measurements().
class MeasurementRecords {
 public:
  virtual ~MeasurementRecords() = default;
  // Its items in `d`, each item's condition and name ("vertical mode").
  virtual int Items(const Dataset& d) const = 0;
  virtual int ConditionOf(const Dataset& d, int item) const = 0;
  virtual std::string ItemName(const Dataset& d, int item) const = 0;
  // Puts condition `from`'s records into condition `to` of *d (a candidate
  // experiment at `speed`, whose model is `at`), as far as they can be
  // measured there; their values are set by Measure.
  virtual void Repeat(const ModelAt& at, int from, int to, double speed, Dataset* d) const = 0;
};
const std::vector<const MeasurementRecords*>& Records();
// The measured modes' records, Records()'s first.
const MeasurementRecords& ModeRecords();

// One kind of measurement. Its items are records of the dataset (a measured
// mode, a static stiffness), each in one condition.
class Measurement {
 public:
  virtual ~Measurement() = default;
  virtual Quantity quantity() const = 0;
  // What it is in words, as experiment advice names it ("mode shape"), and
  // the unit of its values ("Hz", "N/m").
  virtual const char* description() const = 0;
  virtual const char* unit() const = 0;
  // The records its items are (measured modes, static stiffnesses).
  virtual const MeasurementRecords& records() const = 0;
  // What advice calls item of `d` were it measured ("mode shape of the
  // vertical mode").
  virtual std::string Addition(const Dataset& d, int item) const = 0;
  // Its residual rows for the item: 0 where the item lacks it or `o` leaves
  // it out. Of those, how many are scales fitted inside the residual (a
  // shape's), which the data do not observe.
  virtual int Rows(const Dataset& d, int item, const MeasurementOptions& o) const = 0;
  virtual int Scales(const Dataset& d, int item, const MeasurementOptions& o) const { return 0; }
  // "3 frequencies": n observables of this kind, in words.
  virtual std::string Count(int n) const = 0;
  // Whether its rows see the condition's system scaled by one factor (M, C
  // and K together), which changes no mode but every stiffness: structural
  // identifiability (estimation/structure.h) then loses that freedom.
  virtual bool SeesScale() const { return false; }
  // Why `model` cannot give the item at any parameter values (an FRF on a
  // coordinate it lacks), in words naming it; nothing where it can.
  virtual std::optional<std::string> Unfit(const ModalModel& model, const Dataset& d,
                                           int item) const {
    return std::nullopt;
  }
  // (model - measured) / sigma into r[0, Rows). With `params`, dr(row, k) =
  // d r / d (catalogue parameter (*params)[k]): a column per parameter listed. False where the model
  // has no counterpart (no paired mode, a singular static solve).
  virtual bool Evaluate(const Dataset& d, int item, const ModelAt& at,
                        const MeasurementOptions& o, double* r, const std::vector<int>* params,
                        Eigen::Ref<RowMatrix> dr) const = 0;
  // A one-row item's measured value and sigma, the mode label its log
  // misfit belongs to and whether dampers (not stiffnesses) set it
  // (estimation/starts.cc); false for the others.
  virtual bool Scalar(const Dataset& d, int item, const MeasurementOptions& o, double* value,
                      double* sigma, ModeLabel* label, bool* damping) const {
    return false;
  }
  // Adds row `component` of item `item`, residual r, to the misfit table
  // (its entry made by the records' first kind).
  virtual void AddMisfit(const Dataset& d, int item, int component, double r,
                         const MeasurementOptions& o, MisfitTable* t) const = 0;
  // What a report lists of an item beside the measured modes' table (which
  // the mode family fills, estimation/identify.h ModeFit): its measured
  // value, sigma and the model's at `at`. False for the mode family's
  // quantities, and where the model has none.
  virtual bool Compared(const Dataset& d, int item, const ModelAt& at, double* measured,
                        double* sigma, double* model) const {
    return false;
  }
  // Sets what item `item` of *d carries of it to what the test measures of
  // the model at `at` (its condition's), without noise; sigmas are kept.
  // False where the model lacks it.
  virtual bool Measure(const ModelAt& at, int item, const MeasurementOptions& o,
                       Dataset* d) const = 0;
  // Gives *d what the test could add in condition c that it lacks (an
  // unmeasured damping ratio, a static stiffness not measured): the model's
  // value at `at` with the standard error advice assumes.
  virtual void AddUnmeasured(const ModelAt& at, int c, const MeasurementOptions& o,
                             const AdviceSigmas& sigmas, Dataset* d) const = 0;
  // Noise of level `noise` (relative for a frequency, a damping ratio or a
  // static stiffness, absolute for shape components) on the noise-free value
  // the item carries, its sigma set to match; draw() gives N(0, 1).
  virtual void AddNoise(double noise, const std::function<double()>& draw, int item,
                        Dataset* d) const = 0;
};


// What a test measures of a mode: one unit per quantity of the mode family.
class ModeQuantity {
 public:
  virtual ~ModeQuantity() = default;
  virtual Quantity quantity() const = 0;
  virtual const char* description() const = 0;
  virtual const char* unit() const = 0;
  // Whether measured mode m carries it.
  virtual bool In(const MeasuredMode& m) const = 0;
  // Its residual rows for m: 0 where m lacks it or `o` leaves it out.
  virtual int Rows(const MeasuredMode& m, const MeasurementOptions& o) const = 0;
  virtual int Scales(const MeasuredMode& m, const MeasurementOptions& o) const { return 0; }
  virtual std::string Count(int n) const = 0;
  // Adds component `component` of m's rows, residual r, to its misfit.
  virtual void AddMisfit(const MeasuredMode& m, int component, double r, ModeMisfit* w) const = 0;
  // Whether the dampers, not the stiffnesses, set it (estimation/starts.cc).
  virtual bool SetByDampers() const { return false; }
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
  // the standard error of `sigmas` (every component of its plane for a shape).
  virtual void Add(const Mode& mode, const MeasurementOptions& o, const AdviceSigmas& sigmas,
                   MeasuredMode* m) const = 0;
  // Noise of level `noise` on a noise-free value m carries (relative for a
  // frequency or damping ratio, absolute for shape components), its sigma
  // set to match; draw() gives N(0, 1). Nothing where m lacks it.
  virtual void AddNoise(double noise, const std::function<double()>& draw,
                        MeasuredMode* m) const = 0;
};

// The quantities of a measured mode, in the order of its rows.
const std::vector<const ModeQuantity*>& ModeQuantities();

// Every kind, in the order of a condition's rows: a measured mode's
// quantities (mode by mode), then the static stiffnesses.
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
