// Synthetic modal tests: a dataset measured from a known truth model.
#ifndef RINGID_DATASETS_SYNTHETIC_H_
#define RINGID_DATASETS_SYNTHETIC_H_

#include <random>
#include <string>
#include <vector>

#include "datasets/dataset.h"
#include "datasets/measurement.h"
#include "model/rigid_ring_model.h"

namespace ringid {

struct SimulateOptions {
  // Gaussian measurement noise: frequency relative sd, damping ratio relative
  // sd, shape component sd (shapes scaled to a largest component of 1).
  double frequency_noise = 0.0025;
  double damping_noise = 0.10;
  double shape_noise = 0.02;
  double static_noise = 0.02;  // static stiffness, relative sd
  double frf_noise = 0.02;     // an FRF line, sd of re and of im relative to |H|
  bool modes = true;           // the seven modes of each condition
  bool damping = true;
  bool shapes = true;
  // Shapes on all seven belt and rim degrees of freedom plus the hub's x_a,
  // z_a, y_a, as rim accelerometers give them.
  bool hub_components = true;
  // Static stiffnesses measured in each standing condition (contract §10).
  std::vector<StaticDirection> statics;
  // The noise level of quantity q (above).
  double Noise(Quantity q) const;
};

// Measures the seven modes of docs/conventions.md §1 of `truth` under
// `model` in each condition of `dataset` (at its speed, with its own known
// values), the static stiffnesses asked for in each standing one, and the
// FRFs each condition's `frf` block lays out (its inputs, outputs, functions
// and lines): fills `dataset->modes`, `dataset->statics` and each function's
// values (sigmas equal to the noise levels) and leaves its other fields as
// they are. False with a reason when the truth
// model cannot be solved or one of those modes is overdamped.
bool Simulate(const ModalModel& model, const Parameters& truth,
              const SimulateOptions& options, std::mt19937_64* rng,
              Dataset* dataset, std::string* error);

// A standing hammer test's layout (contract §9): four blows on the tread
// (radial and tangential at the top, lateral beside the top, oblique at the
// front), six accelerometers on the tread and one tangential on the rim, all
// 28 functions, lines from low_hz to high_hz every step_hz; the tread at
// radius_m, the rim's sensor at 0.2 m. Values zero until Simulate measures
// them.
Frf HammerTest(double radius_m = 0.31, double low_hz = 5, double high_hz = 250,
               double step_hz = 0.5);

// A drum test's layout (contract §8, §9): the measured contact forces F_x,
// F_z, F_y as inputs, the held axle's five channels as outputs, in-plane
// channels per in-plane force and out-of-plane per lateral force (7
// functions); datasets/examples/drum_spec.json with its default lines.
Frf DrumTest(double low_hz = 4, double high_hz = 160, double step_hz = 2);

// A car tire with every parameter plausible (docs/plausibility.md): the
// belt of the public MF-Swift 205/60R15 example and typical contact values.
Parameters ExampleCarTire();

// What a test engineer knows besides the modes: the inertias and load
// (weighed, measured), the hub mass where set, and the relaxation lengths
// (at standstill only K / sigma is seen) as `known`; the paper's ties; every
// other baseline parameter as `initial`, log-normally spread around the truth.
void SetEngineerPriors(const Parameters& truth, double prior_spread,
                       std::mt19937_64* rng, Dataset* dataset);

// FRFs are per newton, so they weigh the masses: the test engineer need not.
// The belt's mass and the four inertias move from `known` to `initial`,
// log-normally spread around the truth as SetEngineerPriors spreads the rest.
void FreeMasses(const Parameters& truth, double prior_spread, std::mt19937_64* rng,
                Dataset* dataset);

// The largest relative frequency shift over the seven modes of
// docs/conventions.md §1 when `p` of `effect` is set to `value` (infinity
// when a mode is lost).
double LargestShift(const Parameters& truth, const Effect& effect, Param p, double value);

// The value of `p` whose largest frequency shift is `target` (bisection in log).
double ValueForShift(const Parameters& truth, const Effect& effect, Param p, double target);

// The conditions of a test at `speeds` (m/s) x `loads` (N; none: one load,
// the set's) of docs/conventions.md §7: "standing" at 0 m/s, "drum_V"
// otherwise, "_FN" appended for each load, then that condition's known F_cz0.
std::vector<Condition> SimulatedConditions(const std::vector<double>& speeds,
                                           const std::vector<double>& loads);

// A dataset to Simulate into at those conditions: the initial values a tire
// engineer would give (SetEngineerPriors), each load known per condition,
// format 2 when it has several conditions or a load. Name and description are
// the caller's.
Dataset PlanSimulation(const Parameters& truth, double prior_spread,
                       const std::vector<double>& speeds, const std::vector<double>& loads,
                       std::mt19937_64* rng);

// Each speed of `spec` (x each of `loads`, as SimulatedConditions) as a
// condition "obstacle_V" holding the axle's response to rolling over the
// spec's profile (contract §11) with the tandem cam of `truth`, and noise of
// spec.noise times each channel's peak-to-peak there (that its sigma; with
// noise 0, the default's). False
// with `error` naming the spec's field where the test cannot be simulated: a
// cam reaching the profile at t = 0 (but lugs), the tire leaving the road, a
// channel identically zero. `warnings`: where the load changes by more than
// kLargeLoadChange of F_cz0.
inline constexpr double kLargeLoadChange = 0.3;
bool SimulateObstacles(const RigidRingModel& model, const Parameters& truth,
                       const ObstacleSpec& spec, const std::vector<double>& loads,
                       std::mt19937_64* rng, std::vector<Condition>* conditions,
                       std::vector<std::string>* warnings, LoadError* error);

// The effects' names joined by commas, "none" without any.
std::string EffectList(const std::vector<const Effect*>& effects);

}  // namespace ringid

#endif  // RINGID_DATASETS_SYNTHETIC_H_
