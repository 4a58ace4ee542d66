// The options of the operations (operations/*.h) as typed values: each
// struct lists its options once, in `Serialize`, with the option's name and
// meaning, as a report lists its fields (model/archive.h; Drake's config
// structs). Both front ends read that list: the command line registers each
// option as its flag and reads the flags back through it (apps/flags.cc),
// and the Python module takes the same names as keyword arguments (python/).
// Defaults are the library's own (IdentifyOptions, SimulateOptions, ...).
// An option's value is read from its text by operations/option_text.h; what
// one option asks of another is checked by the operation.
//
// In Serialize:  a->Visit("name", &field, "meaning");
// An option more than one operation takes is visited by one function below,
// so that it has one meaning.
#ifndef RINGID_OPERATIONS_OPTIONS_H_
#define RINGID_OPERATIONS_OPTIONS_H_

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "datasets/synthetic.h"
#include "estimation/diagnose.h"
#include "estimation/identifiability.h"
#include "estimation/identify.h"
#include "estimation/plscf.h"
#include "model/effects.h"
#include "model/parameters.h"

namespace ringid {

// Numbers in a unit, none twice, each >= 0 (> 0 when `positive`):
// --speeds=0,10.
struct NumberList {
  std::vector<double> values;
  bool positive = false;
  const char* unit = "";
};

// Parameter values NAME=VALUE, each in its parameter's domain.
using ParameterValues = std::map<Param, double>;

// The options more than one operation takes.
namespace option {
template <class Archive>
void Effects(Archive* a, std::vector<const Effect*>* effects) {
  a->Visit("effects", effects,
           "EFFECT,...: effects of docs/conventions.md §4 to add to the model (diagnose: to its "
           "baseline; the others are tried on top)");
}
template <class Archive>
void Set(Archive* a, ParameterValues* set) {
  a->Visit("set", set,
           "NAME=VALUE,...: parameter values to set over the file's, each in its parameter's "
           "domain; an effect's size among them");
}
template <class Archive>
void Fix(Archive* a, std::vector<Param>* fix) {
  a->Visit("fix", fix,
           "NAME,...: parameters held at their initial values (simulate: written known, at the "
           "truth)");
}
template <class Archive>
void Seed(Archive* a, int* seed) {
  a->Visit("seed", seed, "seed of the random starts, and of the noise in simulate and bench");
}
template <class Archive>
void Speeds(Archive* a, NumberList* speeds) {
  a->Visit("speeds", speeds,
           "V1,V2,...: speeds in m/s (>= 0); simulate: one condition each (0: standing, else "
           "drum_V); predict: the modes at each (a Campbell diagram)");
}
template <class Archive>
void Band(Archive* a, NumberList* band) {
  a->Visit("band", band,
           "LO,HI: use the lines of measured FRFs from LO to HI Hz only (all by default; a fit: "
           "docs/conventions.md §9, the rigid ring does not hold far above its modes)");
}
}  // namespace option

// identify, identifiability, compare, diagnose and ringid.Problem.
struct FitSettings {
  Method method = IdentifyOptions().method;
  int starts = IdentifyOptions().starts;
  int max_iterations = IdentifyOptions().max_iterations;
  int seed = static_cast<int>(IdentifyOptions().seed);
  FrequencyWeighting weighting = ResidualOptions().frequency_weighting;
  double relative_sigma = ResidualOptions().relative_sigma;
  bool shapes = ResidualOptions().use_shapes;
  bool damping = ResidualOptions().use_damping;
  ShapeConvention shape_convention = ResidualOptions().shape_convention;
  Derivatives derivatives = ResidualOptions().derivatives;
  NumberList band{{}, false, "Hz"};
  std::vector<const Effect*> effects;
  Bounds bounds;
  std::vector<Param> fix;
  int threads = 0;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("method", &method, "how to fit: Levenberg-Marquardt or the Downhill Simplex");
    a->Visit("starts", &starts,
             "number of starts: the dataset's initial point, the point matching the measured "
             "frequencies, and points scattered log-uniformly around that");
    a->Visit("max_iterations", &max_iterations,
             "Levenberg-Marquardt iterations per start (and per profile refit) before it stops "
             "unconverged");
    option::Seed(a, &seed);
    a->Visit("weighting", &weighting,
             "frequency residuals weighted by their sigma, or relative to the frequency (eqs. "
             "19-20)");
    a->Visit("relative_sigma", &relative_sigma,
             "relative frequency sigma where the dataset gives none");
    a->Visit("shapes", &shapes, "fit the measured mode shapes");
    a->Visit("damping", &damping, "fit the measured damping ratios");
    a->Visit("shape_convention", &shape_convention,
             "how the measured real shapes were made: as the contract says, or as the paper's "
             "Tables 4-5");
    a->Visit("derivatives", &derivatives,
             "Jacobians by central differences (numeric), from eigenvalue and eigenvector "
             "derivatives and dH = -H dZ H (analytic), or per condition (auto): analytic "
             "where it measures FRFs or static stiffnesses and no modes, numeric where it "
             "measures modes");
    option::Band(a, &band);
    option::Effects(a, &effects);
    a->Visit("bounds", &bounds,
             "NAME:LO:HI,...: bounds in the parameter's units, in place of a factor 1000 around "
             "the start");
    option::Fix(a, &fix);
    a->Visit("threads", &threads,
             "starts (diagnose: and candidate effects; identifiability: and profiles) fitted at "
             "once; 0: the cores, shared among --jobs");
  }
};

struct DiagnoseSettings {
  FitSettings fit;
  double level = DiagnoseOptions().effect_significance;
  double screen = DiagnoseOptions().screen_significance;

  template <class Archive>
  void Serialize(Archive* a) {
    fit.Serialize(a);
    a->Visit("level", &level,
             "significance level of each effect's likelihood-ratio test and of the verdict's "
             "group (the default is Bonferroni-safe for six candidates)");
    a->Visit("screen", &screen,
             "refit only the effects whose score test at the baseline's optimum has a p-value "
             "below this, and the effects whose signatures overlap theirs; 1 refits every "
             "effect");
  }
};

// identifiability.
struct IdentifiabilitySettings {
  FitSettings fit;
  Profiles profiles = IdentifiabilityOptions().profiles;

  template <class Archive>
  void Serialize(Archive* a) {
    fit.Serialize(a);
    a->Visit("profiles", &profiles,
             "identifiability: profile-likelihood intervals (a series of refits per "
             "parameter): auto computes them unless the data measure FRFs, where each refit "
             "is an FRF fit");
  }
};

// extract.
struct ExtractSettings {
  int max_model_order = PlscfOptions{}.max_order;

  template <class Archive>
  void Serialize(Archive* a) {
    a->Visit("max_model_order", &max_model_order,
             "extract: the highest order of pLSCF's matrix-fraction model (each order gives "
             "inputs x order poles); the stabilisation diagram runs from 1 to it");
  }
};

// poles (operations/poles.h).
struct PolesSettings {
  NumberList band{{}, false, "Hz"};  // LO,HI; empty: every line
  std::string units;  // "RESPONSE,REFERENCE", e.g. "g,N"; empty: the file's or the map's

  template <class Archive>
  void Serialize(Archive* a) {
    option::Band(a, &band);
    a->Visit("units", &units,
             "poles: the units of a UFF file's FRFs, RESPONSE,REFERENCE (e.g. g,N or mm/s^2,N: "
             "docs/uff.md), over what the file or the map says; default the file's or the map's");
  }
};

// predict.
struct PredictSettings {
  ParameterValues set;
  std::vector<const Effect*> effects;
  NumberList speeds{{0}, false, "m/s"};
  int lugs_per_revolution = 0;
  // The orders a lug-force measurement reads (docs/forces.md); at most
  // kMaxOrders (model/campbell.h).
  int max_order = 5;
  std::string lug_profile;

  template <class Archive>
  void Serialize(Archive* a) {
    option::Set(a, &set);
    option::Effects(a, &effects);
    option::Speeds(a, &speeds);
    a->Visit("lug_profile", &lug_profile,
             "predict: a lugged tread (ringid-lug-profile/1: a lugs profile of contract §11; "
             "docs/inputs.md); at each of --speeds (> 0), the forces per lug order 1 to "
             "--max_order that its lugs put on the ring through the tandem cam, and the axle's "
             "response to each");
    a->Visit("lugs_per_revolution", &lugs_per_revolution,
             "predict: lug impacts per wheel turn; with --speeds, the lug orders meet the modes "
             "at the critical speeds listed (0: none)");
    a->Visit("max_order", &max_order,
             "predict --lugs_per_revolution, --lug_profile: the highest lug order whose critical "
             "speeds, or forces, are listed (at most 200). The default keeps the orders a lug-force measurement reads "
             "(docs/forces.md) and a list of a few dozen lines: order k meets a mode of f Hz at "
             "2 pi r_e0 f / (k lugs) m/s, so slow speeds alone would add hundreds of orders");
  }
};

// simulate: a dataset measured from a parameter set or, with lug_forces, the
// axle's response to lug forces.
struct SimulateSettings {
  std::vector<const Effect*> effects;
  ParameterValues set;
  double shift = 0;
  double frequency_noise = SimulateOptions().frequency_noise;
  double damping_noise = SimulateOptions().damping_noise;
  double shape_noise = SimulateOptions().shape_noise;
  std::vector<StaticDirection> statics;
  double static_noise = SimulateOptions().static_noise;
  std::string frf;
  bool frf_modes = false;
  std::string obstacle;
  double prior_spread = 0.1;
  std::vector<Param> fix;
  int seed = FitSettings().seed;
  NumberList speeds{{0}, false, "m/s"};
  NumberList loads{{}, true, "N"};
  std::string lug_forces;
  double response_noise = 1 / (10 * std::sqrt(2.0));  // 20 dB

  template <class Archive>
  void Serialize(Archive* a) {
    option::Effects(a, &effects);
    option::Set(a, &set);
    a->Visit("shift", &shift,
             "size the one effect of --effects to shift some frequency by this fraction (e.g. "
             "0.04)");
    a->Visit("frequency_noise", &frequency_noise, "relative frequency noise (sd)");
    a->Visit("damping_noise", &damping_noise, "relative damping-ratio noise (sd)");
    a->Visit("shape_noise", &shape_noise, "shape component noise (sd, shapes scaled to 1)");
    a->Visit("static", &statics,
             "KIND,...: static stiffnesses (vertical, longitudinal, lateral) measured in each "
             "standing condition (contract §10); the dataset is then format 3");
    a->Visit("static_noise", &static_noise, "relative static-stiffness noise (sd)");
    a->Visit("frf", &frf,
             "an FRF test's layout (ringid-frf-spec/1: inputs, outputs, lines, functions, "
             "noise; docs/inputs.md): each condition's FRFs as the model gives them, in place of "
             "its modes; the dataset is then format 3");
    a->Visit("frf_modes", &frf_modes,
             "simulate --frf: write each condition's seven modes beside its FRFs");
    a->Visit("obstacle", &obstacle,
             "an obstacle test's layout (ringid-obstacle-spec/1: speeds, profile, sampling, "
             "channels, noise; docs/inputs.md): adds a condition per speed holding the axle's "
             "response to rolling over the profile (contract §11), beside the conditions of "
             "--speeds; the dataset is then format 3");
    a->Visit("prior_spread", &prior_spread,
             "log-normal spread of the dataset's initial values around the truth");
    option::Fix(a, &fix);
    option::Seed(a, &seed);
    option::Speeds(a, &speeds);
    a->Visit("loads", &loads,
             "F1,F2,...: loads F_cz0 in N (> 0); the conditions are then speeds x loads");
    a->Visit("lug_forces", &lug_forces,
             "simulate: a lug-force file (ringid-lug-forces/1); writes the axle's response to "
             "those forces at --speeds, a response dataset (ringid-lug-response/1)");
    a->Visit("response_noise", &response_noise,
             "simulate --lug_forces: noise on re and on im of each channel, a share of its "
             "amplitude (the default is 20 dB)");
  }
};

// forces.
struct ForcesSettings {
  std::vector<const Effect*> effects;
  ParameterValues set;

  template <class Archive>
  void Serialize(Archive* a) {
    option::Effects(a, &effects);
    option::Set(a, &set);
  }
};

}  // namespace ringid

#endif  // RINGID_OPERATIONS_OPTIONS_H_
