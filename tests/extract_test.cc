// extract (issue 37): the modes in a dataset's FRFs as a modal dataset,
// checked against the model's own modes at the synthetic truth, and the
// two-step route (extract, then identify) against that truth.
#include "operations/extract.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <fstream>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "datasets/pairing.h"
#include "datasets/synthetic.h"
#include "datasets/tir_parameters.h"
#include "estimation/identify.h"
#include "estimation/plscf.h"
#include "report/extract_report.h"
#include "tests/test_support.h"
#include "validation/extract_suite.h"
#include "validation/suites.h"

namespace ringid {
namespace {

// A scattered tire's standing hammer test (lines every 1 Hz), masses free at
// initial values `mass_factor` times the truth, the others 15 % off; written
// to a scratch file, whose path is returned.
std::string HammerFile(const Parameters& truth, double noise, double mass_factor,
                       std::mt19937_64* rng, const std::string& name) {
  Dataset d = PlanSimulation(truth, 0, {0}, {}, rng);
  FreeMasses(truth, 0, rng, &d);
  d.name = name;
  d.conditions[0].frf = HammerTest(0.31, 5, 250, 1.0);
  SimulateOptions so;
  so.modes = false;
  so.frf_noise = noise;
  std::string why;
  EXPECT_TRUE(Simulate(RigidRingModel(), truth, so, rng, &d, &why)) << why;
  for (auto& [q, v] : d.initial) v = truth[q] * (IsMassOrInertia(q) ? mass_factor : 1.15);
  const std::string path = testing::Scratch(name);
  std::ofstream(path) << DatasetToJson(d);
  return path;
}

// The extraction of a scattered tire's (seed) hammer test, as HammerFile
// writes it; *truth the tire.
ExtractResult ExtractedHammer(unsigned seed, double noise, double mass_factor,
                              const std::string& name, Parameters* truth) {
  std::mt19937_64 rng(seed);
  *truth = ScatteredTire(&rng);
  const std::string path = HammerFile(*truth, noise, mass_factor, &rng, name);
  ExtractResult x;
  InputError error;
  EXPECT_TRUE(ExtractDataset(path, ExtractSettings{}, &x, &error)) << error.line;
  return x;
}

TEST(ExtractTest, NoiseFreeFrfsGiveTheModelsModesLabelledAsTheModelLabelsThem) {
  Parameters truth;
  const ExtractResult x = ExtractedHammer(2, 0, 1.2, "extract_noise_free.json", &truth);
  ASSERT_TRUE(x.status.ok()) << x.status.message;
  const ModalSolution s = RigidRingModel().Solve(truth);
  ASSERT_TRUE(s.ok) << s.error;
  ASSERT_EQ(x.dataset.modes.size(), s.modes.size());
  for (const MeasuredMode& m : x.dataset.modes) {
    const auto model = std::find_if(s.modes.begin(), s.modes.end(),
                                    [&](const Mode& k) { return k.label == m.label; });
    ASSERT_NE(model, s.modes.end());
    EXPECT_NEAR(m.frequency_hz / model->frequency_hz, 1, 1e-6) << LabelName(m.label);
    ASSERT_TRUE(m.damping_ratio.has_value());
    EXPECT_NEAR(*m.damping_ratio / model->damping_ratio, 1, 1e-5) << LabelName(m.label);
    // A hammer test's four in-plane coordinates are determined, its two
    // lateral accelerometers leave the out-of-plane shapes undetermined.
    EXPECT_EQ(m.shape.empty(), model->plane() == Plane::kOutOfPlane) << LabelName(m.label);
  }
  EXPECT_EQ(x.poles.size(), s.modes.size());
  // Modes carry no modal mass: every free mass is known at its initial value.
  for (int i = 0; i < kNumParams; ++i) {
    const Param p = ParamAt(i);
    if (!IsMassOrInertia(p)) continue;
    EXPECT_EQ(x.dataset.initial.count(p), 0u) << ParamName(p);
    ASSERT_EQ(x.dataset.known.count(p), 1u) << ParamName(p);
    EXPECT_NEAR(x.dataset.known.at(p) / truth[p], 1.2, 1e-12) << ParamName(p);
  }
  EXPECT_TRUE(std::none_of(x.dataset.conditions.begin(), x.dataset.conditions.end(),
                           [](const Condition& c) { return c.frf.has_value(); }));
}

// At speed: a drum's FRFs at 10 m/s (datasets/examples/drum_spec.json's
// layout, lines every 1 Hz, 2 % noise), where no output is measured at every
// input. Each of the model's seven modes at that speed is extracted, named
// as the model names it (the extracted pole nearest the model's, in λ,
// carries its label), its frequency and damping ratio within 4 of their
// standard errors; the slip lag's root in the band is a real pole.
TEST(ExtractTest, ADrumsFrfsAtSpeedGiveTheModelsModesAtThatSpeedLabelledAsTheModelLabelsThem) {
  const double speed = 10;
  const Parameters truth = ExampleCarTire();
  std::mt19937_64 rng(3);
  Dataset d = PlanSimulation(truth, 0.1, {speed}, {}, &rng);
  FreeMasses(truth, 0.1, &rng, &d);
  d.name = "drum";
  d.conditions[0].frf = DrumTest(4, 160, 1);
  SimulateOptions so;
  so.modes = false;
  so.frf_noise = 0.02;
  std::string why;
  ASSERT_TRUE(Simulate(RigidRingModel(), truth, so, &rng, &d, &why)) << why;
  ExtractResult x;
  ExtractModalDataset(RigidRingModel(), d, PlscfOptions{}, &x);
  ASSERT_TRUE(x.status.ok()) << x.status.message;
  const ModalSolution s = RigidRingModel().Solve(truth, speed);
  ASSERT_TRUE(s.ok) << s.error;
  ASSERT_EQ(x.dataset.modes.size(), s.modes.size());
  for (const Mode& mode : s.modes) {
    const auto nearest = std::min_element(
        x.dataset.modes.begin(), x.dataset.modes.end(), [&](const MeasuredMode& a, const MeasuredMode& b) {
          const auto pole = [](const MeasuredMode& m) {
            const double zeta = *m.damping_ratio, w = 2 * M_PI * m.frequency_hz;
            return std::complex<double>(-zeta * w / std::sqrt(1 - zeta * zeta), w);
          };
          return std::abs(pole(a) - mode.eigenvalue) < std::abs(pole(b) - mode.eigenvalue);
        });
    EXPECT_EQ(nearest->label, mode.label) << LabelName(mode.label);
    ASSERT_TRUE(nearest->frequency_sigma_hz && nearest->damping_sigma) << LabelName(mode.label);
    EXPECT_LT(std::abs(nearest->frequency_hz - mode.frequency_hz), 4 * *nearest->frequency_sigma_hz)
        << LabelName(mode.label);
    EXPECT_LT(std::abs(*nearest->damping_ratio - mode.damping_ratio), 4 * *nearest->damping_sigma)
        << LabelName(mode.label);
  }
  ASSERT_EQ(x.conditions.size(), 1u);
  EXPECT_EQ(x.conditions[0].plscf.blocks.size(), 2u);
  std::vector<double> lags;
  for (const double root : s.real_roots) {
    if (-root / (2 * M_PI) >= 4) lags.push_back(root);
  }
  ASSERT_EQ(x.conditions[0].plscf.real_poles.size(), lags.size());
  for (size_t j = 0; j < lags.size(); ++j) {
    EXPECT_NEAR(x.conditions[0].plscf.real_poles[j] / lags[j], 1, 0.05);
  }
}

// The bench's standing tire 6 (seed 1): its lateral mode's damping climbs
// across pLSCF's orders (0.012 at order 18, 0.036 at 30) and is never
// stable at enough of them, and without it the refinement widened the yaw
// mode (damping 0.15 against the truth's 0.06). Where the refined model
// misses the FRFs, a pole stable in frequency and vector is added if the
// likelihood-ratio test wants it: all seven of the model's modes, each
// within 4 of its standard errors, and chi-square about its degrees of
// freedom.
TEST(ExtractTest, AModeWhoseDampingDoesNotSettleAcrossOrdersIsFoundWhereTheFrfsNeedIt) {
  ExtractSuite suite;
  suite.start_factor = SuiteOptions{}.start_factor;
  suite.frf_noise = SimulateOptions{}.frf_noise;
  std::mt19937_64 rng(SuiteOptions{}.seed);
  Parameters truth;
  Dataset d;
  for (int k = 0; k <= 6; ++k) ASSERT_TRUE(DrawExtractTire(suite, false, &rng, &truth, &d).ok());
  PlscfResult r;
  ExtractModes(*d.conditions[0].frf, PlscfOptions{}, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_TRUE(r.refinement.status.ok()) << r.refinement.status.message;
  const ModalSolution s = RigidRingModel().Solve(truth);
  ASSERT_EQ(r.modes.size(), s.modes.size());
  for (const Mode& mode : s.modes) {
    const auto nearest = std::min_element(r.modes.begin(), r.modes.end(), [&](const auto& a, const auto& b) {
      return std::abs(a.eigenvalue - mode.eigenvalue) < std::abs(b.eigenvalue - mode.eigenvalue);
    });
    EXPECT_LT(std::abs(nearest->frequency_hz - mode.frequency_hz), 4 * nearest->frequency_std_hz)
        << LabelName(mode.label);
    EXPECT_LT(std::abs(nearest->damping_ratio - mode.damping_ratio), 4 * nearest->damping_ratio_std)
        << LabelName(mode.label);
  }
  EXPECT_LT(r.refinement.chi_square, 1.02 * r.refinement.degrees_of_freedom);
}

// The bench's close_pair tire 33: its yaw and lateral modes 0.06 Hz apart
// (46.51 Hz at damping 0.1075, 46.57 at 0.0575), extracted at 46.76 (0.103)
// and 46.56 (0.057). By frequency alone the nearer names swap them; at the
// fit (datasets/pairing.h with the damping ratios) the poles' distance
// names each as the truth does.
TEST(ExtractTest, ModesAFractionOfAHertzApartAreNamedByTheirDamping) {
  Mode yaw, lateral;
  yaw.label = ModeLabel::kYaw;
  yaw.frequency_hz = 46.51;
  yaw.damping_ratio = 0.1075;
  lateral.label = ModeLabel::kLateral;
  lateral.frequency_hz = 46.57;
  lateral.damping_ratio = 0.0575;
  const std::vector<const Mode*> model = {&yaw, &lateral};
  std::vector<internal::ModeToPair> measured = {{46.762, nullptr, std::nullopt, 0.1030},
                                                {46.557, nullptr, std::nullopt, 0.0566}};
  std::vector<int> pick;
  std::vector<internal::PairedBy> by;
  std::string why;
  ASSERT_TRUE(internal::PairModes(measured, model, ShapeConvention::kContract, &pick, &by, &why)) << why;
  EXPECT_EQ(pick, (std::vector<int>{0, 1}));  // 46.762 is the yaw mode
  for (internal::ModeToPair& m : measured) m.damping_ratio.reset();
  ASSERT_TRUE(internal::PairModes(measured, model, ShapeConvention::kContract, &pick, &by, &why)) << why;
  EXPECT_EQ(pick, (std::vector<int>{1, 0}));  // by frequency alone: swapped
}

// The two-step route: with the masses weighed (known at the truth), the
// extracted modes of noise-free FRFs identify the stiffnesses the modes
// determine at the truth.
TEST(ExtractTest, ExtractThenIdentifyWithTheMassesWeighedRecoversTheTruth) {
  Parameters truth;
  const ExtractResult x = ExtractedHammer(3, 0, 1.0, "extract_two_step.json", &truth);
  ASSERT_TRUE(x.status.ok()) << x.status.message;
  const std::string modes = testing::Scratch("extract_two_step_modes.json");
  std::ofstream(modes) << DatasetToJson(x.dataset);
  Dataset d;
  LoadError load;
  ASSERT_TRUE(LoadDataset(modes, &d, &load)) << load.OneLine();
  IdentifyOptions o;
  o.residuals.derivatives = Derivatives::kAnalytic;
  IdentifyResult r;
  Identify(RigidRingModel(), d, o, &r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  int checked = 0;
  for (const ParameterEstimate& e : r.estimates) {
    if (e.identifiable != Identifiability::kYes) continue;
    EXPECT_NEAR(e.value / truth[e.param()], 1, 1e-4) << ParamName(e.param());
    ++checked;
  }
  EXPECT_GE(checked, 6);
}

// Issue 37: with the masses weighed, the route through extraction and the
// direct fit to the FRFs agree within their intervals on every parameter
// both determine, and the direct route's are the narrower (2 % noise).
TEST(ExtractTest, TheTwoRoutesAgreeWithinTheirIntervalsAndTheDirectOnesAreNarrower) {
  Parameters truth;
  const ExtractResult x = ExtractedHammer(5, 0.02, 1.0, "extract_routes.json", &truth);
  ASSERT_TRUE(x.status.ok()) << x.status.message;
  ASSERT_GE(x.routes.size(), 6u);
  int narrower = 0;
  for (const RouteRow& r : x.routes) {
    EXPECT_LT(r.DifferenceSd(), 3) << r.parameter << " " << r.direct << " " << r.modal;
    narrower += r.direct_std < r.modal_std;
  }
  EXPECT_GE(narrower, static_cast<int>(x.routes.size()) - 2);
}

// --parameters: a parameter set's values (the example's truth, weighed
// masses among them) take the place of the dataset's initial values, so the
// masses the modal dataset holds known are the set's, not the guesses'.
TEST(ExtractTest, AParameterSetsMassesAreTheOnesTheModalDatasetHolds) {
  const std::string out = testing::Scratch("extract_with_parameters.json");
  const std::string set = testing::SourcePath("datasets/examples/car_tire.json");
  const testing::RunResult r = testing::Ringid(
      "extract --dataset=" + testing::SourcePath("datasets/examples/car_tire_hammer_frf.json") +
      " --parameters=" + set + " --output=" + out);
  ASSERT_EQ(r.status, 0) << r.err;
  Dataset d;
  LoadError load;
  ASSERT_TRUE(LoadDataset(out, &d, &load)) << load.OneLine();
  Parameters p;
  std::vector<std::string> notes;
  ASSERT_TRUE(LoadParameters(set, {}, &p, &load, &notes)) << load.OneLine();
  int masses = 0;
  for (const auto& [q, v] : d.known) {
    if (!IsMassOrInertia(q)) continue;
    EXPECT_EQ(v, p[q]) << ParamName(q);
    ++masses;
  }
  EXPECT_EQ(masses, 5);
  EXPECT_EQ(d.modes.size(), 7u);
}

TEST(ExtractTest, ADatasetWithoutFrfsIsOneLineExitTwoAndNothingWritten) {
  const std::string out = testing::Scratch("extract_never_written.json");
  std::remove(out.c_str());
  const std::string table1 = testing::SourcePath("datasets/paper/table1.json");
  const testing::RunResult r = testing::Ringid("extract --dataset=" + table1 + " --output=" + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("table1.json: conditions: no condition has an frf block"), std::string::npos)
      << r.err;
  EXPECT_FALSE(std::ifstream(out).good());
  const testing::RunResult bad = testing::Ringid("extract --dataset=" + table1 + " --max_model_order=0 --output=" + out);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--max_model_order"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::ifstream(out).good());
}


// The report (--report) of noise-free FRFs: each function's LSFD synthesis
// is the measured function (FRAC >= 0.999, and equal to 1e-5 of its peak),
// and the stable poles of the diagram's highest orders hold the model's
// seven modes at the truth.
TEST(ExtractTest, TheReportOfNoiseFreeFrfsSynthesisesEachFunctionAndItsDiagramHoldsTheModes) {
  std::mt19937_64 rng(2);
  const Parameters truth = ScatteredTire(&rng);
  const std::string path = HammerFile(truth, 0, 1.2, &rng, "extract_report_noise_free.json");
  const std::string modes = testing::Scratch("extract_report_modes.json");
  const std::string report_path = testing::Scratch("extract_report.json");
  const testing::RunResult run = testing::Ringid("extract --dataset=" + path + " --output=" +
                                                 modes + " --report=" + report_path);
  ASSERT_EQ(run.status, 0) << run.err;
  ExtractReport report;
  std::string error;
  ASSERT_TRUE(ReadReport(Json::parse(testing::ReadFile(report_path)), &report, &error)) << error;
  Dataset d;
  LoadError load;
  ASSERT_TRUE(LoadDataset(path, &d, &load)) << load.OneLine();
  const Frf& frf = *d.conditions[0].frf;
  ASSERT_EQ(report.body.conditions.size(), 1u);
  const ExtractCondition& c = report.body.conditions[0];
  ASSERT_TRUE(c.status.ok()) << c.status.message;
  ASSERT_EQ(c.functions.size(), frf.functions.size());
  int coupled = 0;
  for (size_t k = 0; k < frf.functions.size(); ++k) {
    const FrfFit& f = c.functions[k];
    const FrfFunction& fn = frf.functions[k];
    EXPECT_EQ(f.output, frf.outputs[fn.output].name);
    EXPECT_EQ(f.input, frf.inputs[fn.input].name);
    ASSERT_GT(f.lines(), 100);
    // The measured curve is the dataset's, line for line; the model's
    // function there (noise-free) is the truth the synthesis must meet.
    std::complex<double> cross = 0;
    double measured_norm = 0, synthesised_norm = 0, peak = 0, worst = 0;
    for (int l = 0; l < f.lines(); ++l) {
      const auto at = std::find(frf.frequencies_hz.begin(), frf.frequencies_hz.end(),
                                f.frequency_hz[l]);
      ASSERT_NE(at, frf.frequencies_hz.end()) << f.frequency_hz[l];
      const std::complex<double> h = fn.h[at - frf.frequencies_hz.begin()];
      const std::complex<double> m(f.measured_re[l], f.measured_im[l]);
      const std::complex<double> x(f.model_re[l], f.model_im[l]);
      EXPECT_EQ(m, h) << f.output << "/" << f.input << " at " << f.frequency_hz[l] << " Hz";
      cross += std::conj(m) * x;
      measured_norm += std::norm(m);
      synthesised_norm += std::norm(x);
      peak = std::max(peak, std::abs(m));
      worst = std::max(worst, std::abs(x - m));
    }
    const std::string name = f.output + "/" + f.input;
    if (peak == 0) {  // a function the structure does not couple: FRAC not defined
      EXPECT_TRUE(std::isnan(f.frac)) << name;
      EXPECT_LT(std::sqrt(synthesised_norm), 1e-9) << name;
      continue;
    }
    ++coupled;
    EXPECT_NEAR(f.frac, std::norm(cross) / (measured_norm * synthesised_norm), 1e-12) << name;
    EXPECT_GE(f.frac, 0.999) << name;
    EXPECT_LT(worst, 1e-5 * peak) << name;
  }
  EXPECT_GE(coupled, 14);  // a hammer test's in-plane and lateral functions
  // Each of the highest orders holds every mode as a stable pole.
  const ModalSolution s = RigidRingModel().Solve(truth);
  ASSERT_TRUE(s.ok) << s.error;
  ASSERT_EQ(s.modes.size(), 7u);
  ASSERT_EQ(c.blocks.size(), 1u);  // a hammer test measures every output at every input
  const std::vector<DiagramOrder>& diagram = c.blocks[0].diagram;
  ASSERT_GE(diagram.size(), 5u);
  for (size_t o = diagram.size() - 5; o < diagram.size(); ++o) {
    for (const Mode& m : s.modes) {
      const auto near = std::find_if(diagram[o].poles.begin(), diagram[o].poles.end(),
                                     [&](const DiagramPole& p) {
                                       return p.stable() &&
                                              std::abs(p.frequency_hz / m.frequency_hz - 1) < 1e-6;
                                     });
      ASSERT_NE(near, diagram[o].poles.end())
          << LabelName(m.label) << " at order " << diagram[o].order;
      EXPECT_NEAR(near->damping_ratio / m.damping_ratio, 1, 1e-5) << LabelName(m.label);
    }
  }
  // The physical poles are those of the modal dataset written beside it.
  ASSERT_EQ(report.body.poles.size(), s.modes.size());
  for (const ExtractedPole& p : report.body.poles) {
    ASSERT_TRUE(p.label.has_value());
    const auto model = std::find_if(s.modes.begin(), s.modes.end(),
                                    [&](const Mode& m) { return m.label == *p.label; });
    ASSERT_NE(model, s.modes.end());
    EXPECT_NEAR(p.frequency_hz / model->frequency_hz, 1, 1e-6) << LabelName(*p.label);
  }
}

// --report is written with the dataset or neither is.
TEST(ExtractTest, TheReportAndTheDatasetAreWrittenTogetherOrNotAtAll) {
  const std::string out = testing::Scratch("extract_together.json");
  const std::string report = testing::Scratch("extract_together_report.json");
  std::remove(out.c_str());
  std::remove(report.c_str());
  const std::string table1 = testing::SourcePath("datasets/paper/table1.json");
  testing::RunResult r = testing::Ringid("extract --dataset=" + table1 + " --output=" + out +
                                         " --report=" + report);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("no condition has an frf block"), std::string::npos) << r.err;
  EXPECT_FALSE(testing::Exists(out));
  EXPECT_FALSE(testing::Exists(report));
  const std::string frfs = testing::SourcePath("datasets/examples/car_tire_hammer_frf.json");
  r = testing::Ringid("extract --dataset=" + frfs + " --output=" + out + " --report=" + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("--report: " + out + " is also --output"), std::string::npos) << r.err;
  EXPECT_FALSE(testing::Exists(out));
  r = testing::Ringid("extract --dataset=" + frfs + " --output=" + out + " --report=" +
                      testing::Scratch("no_such_directory/report.json"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--report: "), std::string::npos) << r.err;
  EXPECT_FALSE(testing::Exists(out));
  r = testing::Ringid("extract --dataset=" + frfs + " --output=" + out + " --report=" + report);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(testing::Exists(out));
  EXPECT_TRUE(testing::Exists(report));
  EXPECT_NE(r.out.find("wrote " + out + " (7 modes from " + frfs + ") and " + report),
            std::string::npos) << r.out;
}

}  // namespace
}  // namespace ringid
