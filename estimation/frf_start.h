// Issue 36 item 2: a start for a fit to FRFs from the modes in them. A fit to
// FRFs from a far start stops where a model peak sits beside a measured one;
// the modal route's starts (MatchFrequencies) find its optimum from far. So:
// the modes each condition's FRFs hold (estimation/plscf.h), with shapes on
// the model's coordinates, identified as modal data with one mass held (modes
// carry no scale), give the FRF fit a start whose peaks lie on the measured
// ones (docs/development.md, "Starts and stopping").
#ifndef RINGID_ESTIMATION_FRF_START_H_
#define RINGID_ESTIMATION_FRF_START_H_

#include <cmath>
#include <complex>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "datasets/dataset.h"
#include "datasets/frf.h"
#include "estimation/plscf.h"
#include "model/modal.h"
#include "model/rigid_ring_model.h"

namespace ringid {

namespace internal {

class ParameterSetup;  // estimation/setup.h

// A mode an extraction found in a condition's FRFs: its damped frequency,
// damping ratio and complex shape on the block's outputs (residues of one
// reference), which need not be normalised.
struct FrfMode {
  double frequency_hz = 0;
  double damping_ratio = 0;
  Eigen::VectorXcd outputs;
  int stable_orders = 0;  // of the stabilisation diagram (0: not from one)
  // Standard errors of the refinement (estimation/modal_refine.h); NaN without.
  double frequency_std_hz = NAN, damping_ratio_std = NAN;
};

// A mode's shape is given on the coordinates the outputs determine (those
// in the row space of their combinations) where these carry all but this
// share of its outputs (norm squared); elsewhere it has none.
inline constexpr double kUndeterminedShare = 0.1;
// The modal stage is labelled and fitted at most this many times.
inline constexpr int kLabelRounds = 3;

// The shape of `mode` on the model's coordinates: the least-squares solution
// of the outputs' combinations (contract §9; a velocity or acceleration
// output divided by its pole's power) on the coordinates they determine,
// phase-aligned as a measured shape (docs/conventions.md §2: the largest
// component real, scaled to 1). Empty where an output is an axle channel or
// the determined coordinates miss more than kUndeterminedShare of it: a
// hammer test's two lateral accelerometers do not separate y_b, gamma_b and
// psi_b.
std::vector<std::pair<Dof, double>> ShapeOnCoordinates(const ModalModel& model, const Frf& frf,
                                                      const FrfMode& mode);

// The labels of `found` (at most as many as `at` has modes): the assignment
// by the complex MAC on the outputs between each found mode and the model's
// modes at `at` mapped onto the outputs, the largest sum. Empty where an
// output is an axle channel.
std::vector<ModeLabel> LabelsOnOutputs(const ModalModel& model, const Frf& frf,
                                       const std::vector<FrfMode>& found, const ModalSolution& at);

// The dataset the modal stage fits: each condition with an frf block and no
// measured modes gets `found[c]` as its modes (at most as many as the model
// has, the strongest first), labelled by the model at `at[c]`
// (LabelsOnOutputs; by frequency, datasets/pairing.h, for axle channels);
// the frf blocks dropped; the first free mass or inertia made known at its
// initial value unless static stiffnesses set the scale. False, with `why`,
// where no condition gives a mode.
bool ModalStageDataset(const ModalModel& model, const Dataset& d,
                       const std::vector<std::vector<FrfMode>>& found,
                       const std::vector<Parameters>& at, Dataset* out, std::string* why);

// The modes each condition's FRFs hold (pLSCF and LSFD at their defaults,
// estimation/plscf.h), per condition; empty where no condition's FRFs give one.
// `why` gets the first extraction's failure, where one fails; `results`, where
// given, each condition's extraction (a default one without an frf block).
std::vector<std::vector<FrfMode>> ModesInFrfs(const Dataset& d, const PlscfOptions& o = {},
                                             std::string* why = nullptr,
                                             std::vector<PlscfResult>* results = nullptr);

// The modes the modal stage starts from: ModesInFrfs without the
// refinement (it costs about 60 ms a hammer test of 28 FRFs, a quarter of a
// one-start fit, BM_FrfFit, and the FRF fit refines the modes itself), of
// the conditions whose outputs name their modes. A drum's outputs are axle
// channels, which name its modes by frequency alone: from initial values a
// factor 3 off that names them wrongly (bench --suite=frf's standing + drum
// tires with the drum's modes in the stage: the best fit in 19 of 20, not
// 20, at 15.2 s a fit, not 3.8). A drum alone has no stage (with one, 20
// drum tires at 10 m/s were not named better). Empty where no condition
// gives a mode.
std::vector<std::vector<FrfMode>> StageModes(const Dataset& d);

// A start for `setup` (of `d`, a dataset with FRFs) from the point `from`:
// `found` (StageModes) labelled by the model at `from`, fitted as modal data
// from there (kModalStageStarts starts: `from` and the point matching its
// frequencies), labelled again at the fit and refitted until the labels hold
// (kLabelRounds); the fitted values in `setup`'s coordinates, the mass it
// held at `from`'s value. None where there are no modes or the modal stage
// fails. `stage`, where given, gets the modal dataset of the fit returned.
inline constexpr int kModalStageStarts = 2;
std::optional<Eigen::VectorXd> FrfModalStart(const ModalModel& model, const Dataset& d,
                                             const ParameterSetup& setup,
                                             const std::vector<std::vector<FrfMode>>& found,
                                             const Eigen::VectorXd& from,
                                             Dataset* stage = nullptr);

// Where the fit from FrfModalStart's start ends poor: the modes its `stage`
// fitted without a shape (2 to kMaxPermutedLabels of them) with their labels
// in each other order, each fitted as modal data from `from`; the start of
// the least `frf_cost` (the FRFs' cost at a point in `setup`'s coordinates).
// Two lateral sensors do not tell the three out-of-plane modes apart, and
// their output MAC can label them wrongly. None where no other order fits.
inline constexpr size_t kMaxPermutedLabels = 3;
std::optional<Eigen::VectorXd> OtherLabelOrderStart(
    const ModalModel& model, const ParameterSetup& setup, const Dataset& stage,
    const Eigen::VectorXd& from, const std::function<double(const Eigen::VectorXd&)>& frf_cost);

}  // namespace internal
}  // namespace ringid

#endif  // RINGID_ESTIMATION_FRF_START_H_
