// The flags of ringid (DEFINE_* in apps/flags.cc: each flag's meaning, for
// every command that takes it) and the readers that turn them into options,
// effects, datasets and provenance, each false or exit 2 with one line naming
// the flag on bad input. Which commands take a flag is the table of commands
// in apps/ringid.cc; `ringid COMMAND --help` shows both.
#ifndef RINGID_APPS_FLAGS_H_
#define RINGID_APPS_FLAGS_H_

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <gflags/gflags.h>

#include "apps/campaign.h"
#include "apps/command_line.h"
#include "datasets/dataset.h"
#include "estimation/identify.h"
#include "model/effects.h"
#include "model/rigid_ring_model.h"
#include "model/spelling.h"
#include "report/report.h"

DECLARE_string(dataset);
DECLARE_string(parameters);
DECLARE_string(output);
DECLARE_string(save_parameters);
DECLARE_string(method);
DECLARE_int32(starts);
DECLARE_int32(max_iterations);
DECLARE_int32(seed);
DECLARE_string(weighting);
DECLARE_double(relative_sigma);
DECLARE_bool(shapes);
DECLARE_bool(damping);
DECLARE_string(shape_convention);
DECLARE_string(derivatives);
DECLARE_string(truth);
DECLARE_string(set);
DECLARE_double(frequency_noise);
DECLARE_double(damping_noise);
DECLARE_double(shape_noise);
DECLARE_double(shift);
DECLARE_double(prior_spread);
DECLARE_string(speeds);
DECLARE_string(loads);
DECLARE_string(suite);
DECLARE_int32(replicates);
DECLARE_int32(lugs_per_revolution);
DECLARE_int32(max_order);
DECLARE_string(lug_forces);
DECLARE_string(uff);
DECLARE_bool(force);
DECLARE_bool(keep_going);
DECLARE_string(map);
DECLARE_double(response_noise);
DECLARE_string(markdown);
DECLARE_string(output_dir);
DECLARE_int32(jobs);
DECLARE_string(shard);
DECLARE_string(input);
DECLARE_string(figures_dir);
DECLARE_string(bounds);
DECLARE_string(fix);
DECLARE_string(effects);
DECLARE_double(level);
DECLARE_int32(threads);
DECLARE_string(format);

namespace ringid {

// The flags a command takes (the table of commands in apps/ringid.cc and the
// Python module's keyword arguments): every fitting command's, predict's,
// simulate's and forces'.
const std::vector<std::string>& FitFlags();
const std::vector<std::string>& PredictFlags();
const std::vector<std::string>& SimulateFlags();
const std::vector<std::string>& ForcesFlags();

// "ringid: LINE" on standard error; kExitUsage.
int Usage(const std::string& line);
// `text` written to `path` whole or not at all; kExitOk, else Usage.
int Write(const std::string& path, const std::string& text);

// The input files the flags name, as (flag, path): each goes into the
// provenance, and no output may overwrite one. A campaign names each report's
// own dataset file.
std::vector<std::pair<std::string, std::string>> Inputs(const std::string& dataset = FLAGS_dataset);
// This process's provenance, with the inputs its flags named.
Provenance ThisRun(int argc, char** argv, std::optional<long> seed,
                   const std::string& dataset = FLAGS_dataset);

// A number that is the whole of `text`.
bool ParseNumber(const std::string& text, double* v);
// --effects=EFFECT,...
bool ParseEffects(std::vector<const Effect*>* effects, std::string* error);
// --set=NAME=VALUE,... (apps/flags.cc says what each must be).
bool ParseSet(std::map<Param, double>* set, std::string* error);
// --bounds=NAME:LO:HI,...
bool ParseBounds(Bounds* bounds, std::string* error);
// The parameters --fix=NAME,... names.
bool ParseFix(std::vector<Param>* fixed, std::string* error);
// --fix=NAME,... applied to a loaded dataset.
bool ApplyFix(Dataset* d, std::string* error);
// --NAME=X1,X2,...: finite numbers, each >= 0 (or > 0 when `positive`),
// none twice.
bool ParseNumberList(const char* name, const std::string& text, bool positive, const char* unit,
                     std::vector<double>* values, std::string* error);

// --NAME=VALUE of an enum flag; the valid names on error.
template <class E>
bool ParseFlag(const char* name, const std::string& value, E* e, std::string* error) {
  const std::optional<E> parsed = FromString<E>(value);
  if (parsed) *e = *parsed;
  else *error = std::string("--") + name + ": " + UnknownName("value", value, NamesOf<E>());
  return parsed.has_value();
}

// The flags every fitting command shares, read into options and the model's
// effects.
bool ReadFitOptions(IdentifyOptions* o, std::vector<const Effect*>* effects, std::string* error);
// The same and the one dataset of --dataset, --fix applied. A directory or
// a list in --dataset is refused as a campaign's, which `campaigns` (identify
// and diagnose) run with --output_dir.
bool ReadFitInputs(IdentifyOptions* o, std::vector<const Effect*>* effects, Dataset* d,
                   std::string* error, bool campaigns = false);

// The effect of the catalogue that `p` belongs to, or null for a parameter
// of the baseline.
const Effect* EffectOwning(Param p);
// The parameters of `model` that `p` does not set, in the model's order.
std::vector<Param> Missing(const RigidRingModel& model, const Parameters& p);
// The one line for the parameters the model needs and neither `source` (a
// parameter set, a dataset or a .tir) nor --set gives.
std::string MissingParameters(const std::string& source, const std::vector<Param>& missing,
                              const std::vector<std::string>& notes = {});
// simulate: every effect of --effects has a size and every effect size in
// --set has its effect in --effects.
bool CheckEffectSizes(const std::vector<const Effect*>& effects,
                      const std::map<Param, double>& set, const Parameters& file,
                      std::string* error);

// The flags that decide a fitting command's results (those of every fitting
// command less --dataset, --output and --threads).
const std::vector<std::string>& ResultFlags();
// Their values, NAME=VALUE, with --level: what a campaign's reports record.
std::vector<std::string> CampaignOptions();

// --output_dir: a campaign of `command` over --dataset (apps/campaign.h).
int Campaign(int argc, char** argv, ReportKind command, const ModalModel& model,
             const CampaignWork& work);

// The end of an analysis of one dataset: bad input is exit 2; otherwise its
// text, its report of type R at --output, and exit 0 or 1 by its status.
template <class R, class Data, class Result>
int Finish(int argc, char** argv, const Data& d, const Result& r) {
  if (r.status.invalid_input()) return Usage(FLAGS_dataset + ": " + r.status.message);
  std::printf("%s", r.FullReport().c_str());
  if (!FLAGS_output.empty()) {
    const int rc = Write(FLAGS_output, ReportText(R{ThisRun(argc, argv, FLAGS_seed), {d.name, r}}));
    if (rc != kExitOk) return rc;
  }
  return r.status.ok() ? kExitOk : kExitFailure;
}

}  // namespace ringid

#endif  // RINGID_APPS_FLAGS_H_
