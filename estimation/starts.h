// Where the local fits of one identification start: the user's initial
// values, a point computed from the measured frequencies, and points
// scattered around it (docs/development.md, "Starts and stopping").
#ifndef RINGID_ESTIMATION_STARTS_H_
#define RINGID_ESTIMATION_STARTS_H_

#include <functional>
#include <vector>

#include <Eigen/Core>

#include "estimation/types.h"
#include "estimation/fit.h"
#include "estimation/identify.h"
#include "estimation/residuals.h"
#include "model/enum_names.h"

namespace ringid {

namespace internal {

StartAgreement AssessStarts(const ParameterSetup& setup,
                            const std::vector<double>& costs,
                            const std::vector<Eigen::VectorXd>& ends);

// How many shapes the residuals fit a scale for (Measurement::Scales): each
// takes a degree of freedom from AssessFit.
int ShapeScales(const ModalResiduals& residuals);

// Whether a fit of `cost` passes AssessFit's chi-square test (p >= kPoorFitP
// on the residuals less the free coordinates and the shape scales): a start
// whose fit does, needs no other route to the optimum.
bool FitsWithinNoise(const ModalResiduals& residuals, double cost);

// Levenberg-Marquardt iterations the FRF fit from a dataset's initial values
// has to pass FitsWithinNoise before the modal stage is asked for a start
// (estimation/frf_start.h); from values 15 % off the hammer test's takes 10.
inline constexpr int kDirectIterations = 15;


// MatchFrequencies' figures (docs/development.md, which a test keeps saying
// them): a parameter moves with a label's misfit when a factor 2 in it moves
// that label's frequency (damping ratio) by more than about 3.5 %; at most
// kMatchRounds rounds.
inline constexpr double kOwnership = 0.05;
inline constexpr int kMatchRounds = 8;

// x0 with every free stiffness (IsStiffness) moved so that the measured modes
// get their measured frequencies, and with measured damping ratios every
// free sidewall damper likewise: the closed form f^2 ~ k a tire engineer
// uses (docs/tir.md), with the model's own sensitivities for the coupling.
// Each parameter belongs to the measured label whose frequency (damping
// ratio) it moves most, at least kOwnership in d log f / d log p; the
// parameters of one label move by one common log step, the least-squares
// step of that label's log misfit. kMatchRounds rounds at most, each step at most a
// factor 4, clipped to the box; x0 itself where the model cannot be solved.
Eigen::VectorXd MatchFrequencies(const ModalResiduals& residuals, const Eigen::VectorXd& x0,
                                 const Box& box);

struct Start {
  Eigen::VectorXd x;
  StartOrigin origin = StartOrigin::kInitial;
};

// `starts` points: x0 (the user's), MatchFrequencies(x0) where it differs,
// then points scattered around the matched one and x0 in turn (x0 with its
// dampers lowered where a mode is overdamped there), a Latin hypercube
// log-uniform within a factor `factor` for log coordinates and within +-1
// typical scale for the others, clipped to the box. A scattered draw where
// `usable` is false is drawn again, up to 100 times, then kept.
std::vector<Start> PlanStarts(const ModalResiduals& residuals, const Eigen::VectorXd& x0,
                              const Box& box, int starts, double factor, unsigned seed,
                              const std::function<bool(const Eigen::VectorXd&)>& usable);

}  // namespace internal
}  // namespace ringid

#endif  // RINGID_ESTIMATION_STARTS_H_
