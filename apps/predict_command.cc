#include "apps/predict_command.h"

#include <algorithm>
#include <cstdio>

#include "apps/flags.h"
#include "apps/reports.h"
#include "datasets/tir_parameters.h"
#include "model/campbell.h"
#include "report/report.h"

namespace ringid {
namespace {

// predict --speeds (and --lugs_per_revolution): the modes at each speed and
// the critical speeds, into body.
bool AtSpeeds(const RigidRingModel& model, const Parameters& p, PredictBody* body,
              std::string* error) {
  std::vector<double> speeds;
  if (!ParseNumberList("speeds", FLAGS_speeds, false, "m/s", &speeds, error)) return false;
  if (FLAGS_lugs_per_revolution < 0) {
    *error = "--lugs_per_revolution: must not be negative";
    return false;
  }
  if (FLAGS_max_order < 1 || FLAGS_max_order > kMaxOrders) {
    *error = "--max_order: must lie in [1, " + std::to_string(kMaxOrders) + "]";
    return false;
  }
  std::sort(speeds.begin(), speeds.end());
  if (speeds == std::vector<double>{0}) {  // standing: the modes above
    if (FLAGS_lugs_per_revolution > 0) {
      *error = "--lugs_per_revolution: needs --speeds (the lug orders meet the modes at speed)";
      return false;
    }
    return true;
  }
  body->speeds.emplace();
  for (double v : speeds) {
    SpeedModes at;
    at.speed_m_s = v;
    for (const Mode& m : model.Solve(p, v).modes) at.modes[m.label] = {m.frequency_hz, m.damping_ratio};
    body->speeds->push_back(at);
  }
  if (FLAGS_lugs_per_revolution > 0) {
    body->lugs_per_revolution = FLAGS_lugs_per_revolution;
    body->r_e0 = p[Param::r_e0];
    body->max_order = FLAGS_max_order;
    body->critical_speeds =
        CriticalSpeeds(model, p, FLAGS_lugs_per_revolution, speeds, FLAGS_max_order);
  }
  return true;
}

// The modes of every condition of `d`, each with its per-condition values.
std::vector<SpeedModes> ByCondition(const RigidRingModel& model, const Dataset& d,
                                    const std::map<Param, double>& set) {
  std::vector<SpeedModes> out;
  for (size_t c = 0; c < d.conditions.size(); ++c) {
    Parameters p = InitialParameters(d, static_cast<int>(c));
    for (const auto& [q, v] : set) p[q] = v;
    SpeedModes at{d.conditions[c].name, d.conditions[c].speed_m_s, {}};
    for (const Mode& m : model.Solve(p, at.speed_m_s).modes) {
      at.modes[m.label] = {m.frequency_hz, m.damping_ratio};
    }
    out.push_back(at);
  }
  return out;
}

}  // namespace

bool PredictBodyOf(const Parameters& parameters, const Dataset* d,
                   const std::map<Param, double>& set, const std::vector<const Effect*>& effects,
                   const std::string& source, const std::vector<std::string>& notes,
                   PredictBody* body, std::string* solve_error, std::string* error) {
  Parameters p = parameters;
  if (d) {
    p = InitialParameters(*d);
    for (const auto& [q, v] : set) p[q] = v;
  }
  const RigidRingModel model(effects);
  const std::vector<Param> missing = Missing(model, p);
  if (!missing.empty()) {
    *error = MissingParameters(source, missing, notes);
    return false;
  }
  const ModalSolution s = model.Solve(p);
  *body = PredictBody::From(s);
  if (!notes.empty()) body->parameter_notes = notes;
  if (d && d->conditions.size() > 1) body->conditions = ByCondition(model, *d, set);
  if (!AtSpeeds(model, p, body, error)) return false;
  solve_error->clear();
  if (!s.ok) *solve_error = s.error.empty() ? std::string("the model cannot be solved") : s.error;
  return true;
}

int Predict(int argc, char** argv) {
  std::string error;
  std::vector<const Effect*> effects;
  if (!ParseEffects(&effects, &error)) return Usage(error);
  if (FLAGS_parameters.empty() == FLAGS_dataset.empty()) {
    return Usage("predict needs exactly one of --parameters=FILE or --dataset=FILE");
  }
  if (!CheckOutputs({{"output", FLAGS_output}}, Inputs(), &error)) return Usage(error);
  std::map<Param, double> set;
  if (!ParseSet(&set, &error)) return Usage(error);
  Parameters p;
  LoadError load;
  std::vector<std::string> notes;
  Dataset d;
  if (!FLAGS_parameters.empty()) {  // a .tir by its extension
    if (!LoadParameters(FLAGS_parameters, set, &p, &load, &notes)) return Usage(load.OneLine());
  } else if (!LoadDataset(FLAGS_dataset, &d, &load)) {
    return Usage(load.OneLine());
  }
  const std::string& source = FLAGS_parameters.empty() ? FLAGS_dataset : FLAGS_parameters;
  PredictBody body;
  std::string solve_error;
  if (!PredictBodyOf(p, FLAGS_parameters.empty() ? &d : nullptr, set, effects, source, notes,
                     &body, &solve_error, &error)) {
    return Usage(error);
  }
  if (!solve_error.empty()) std::fprintf(stderr, "ringid: predict: %s\n", solve_error.c_str());
  else std::printf("%s", body.FullReport().c_str());
  if (!FLAGS_output.empty()) {
    const int rc = Write(FLAGS_output, ReportText(PredictReport{ThisRun(argc, argv, std::nullopt), body}));
    if (rc != kExitOk) return rc;
  }
  return solve_error.empty() ? kExitOk : kExitFailure;
}

}  // namespace ringid
