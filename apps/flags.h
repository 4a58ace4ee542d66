// The flags of ringid (DEFINE_* in apps/flags.cc, and the options of
// operations/options.h registered from their lists: each flag's meaning, for
// every command that takes it) and the readers that turn them into settings,
// options, datasets and provenance, each false or exit 2 with one line naming
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
#include "operations/option_text.h"
#include "operations/options.h"
#include "report/report.h"

// The flags of files and of the commands outside operations/ (DEFINE_* in
// apps/flags.cc); the options of operations/options.h are flags registered
// from their lists, read through ReadSettings and ReadFlag.
DECLARE_string(dataset);
DECLARE_string(parameters);
DECLARE_string(output);
DECLARE_string(save_parameters);
DECLARE_string(truth);
DECLARE_string(report);
DECLARE_string(suite);
DECLARE_int32(replicates);
DECLARE_string(uff);
DECLARE_bool(force);
DECLARE_bool(keep_going);
DECLARE_string(map);
DECLARE_string(markdown);
DECLARE_string(output_dir);
DECLARE_int32(jobs);
DECLARE_string(shard);
DECLARE_string(input);
DECLARE_string(figures_dir);
DECLARE_string(format);

namespace ringid {

// The flags a command takes (the table of commands in apps/ringid.cc): every
// fitting command's, predict's, simulate's and forces', their options those
// of operations/options.h.
const std::vector<std::string>& FitFlags();
const std::vector<std::string>& PredictFlags();
const std::vector<std::string>& SimulateFlags();
const std::vector<std::string>& ForcesFlags();
const std::vector<std::string>& ExtractFlags();

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

// The text a flag holds (gflags' record of it).
std::string FlagText(const std::string& name);
// Settings S from the flags: each option of its list given on the command
// line, read through the list in its order; false with the line naming the
// first that is bad.
template <class S>
bool ReadSettings(S* settings, std::string* error) {
  for (const OptionInfo& o : OptionsOf<S>()) {
    gflags::CommandLineFlagInfo info;
    if (!gflags::GetCommandLineFlagInfo(o.name.c_str(), &info) || info.is_default) continue;
    if (!SetOption(settings, o.name, info.current_value, error)) return false;
  }
  return true;
}
// One option's value from its flag (`value` as it is where not given).
template <class T>
bool ReadFlag(const std::string& name, T* value, std::string* error) {
  gflags::CommandLineFlagInfo info;
  if (!gflags::GetCommandLineFlagInfo(name.c_str(), &info) || info.is_default) return true;
  return OptionFromText(name, info.current_value, value, error);
}
// --seed, valid once the command line is read (gflags checked it).
int SeedFlag();
// --set=NAME=VALUE,...
bool ParseSet(ParameterValues* set, std::string* error);

// The settings of the fitting commands and the library's options from them
// (the cores shared among a campaign's --jobs), with --dataset given.
bool ReadFitOptions(FitSettings* s, IdentifyOptions* o, std::string* error);
bool ReadDiagnoseOptions(DiagnoseSettings* s, DiagnoseOptions* o, std::string* error);
bool ReadIdentifiabilityOptions(IdentifiabilitySettings* s, IdentifiabilityOptions* o,
                                std::string* error);
// The one dataset of --dataset, s.fix applied (the outputs checked first).
// A directory or a list in --dataset is refused as a campaign's, which
// `campaigns` (identify and diagnose) run with --output_dir.
bool ReadFitDataset(const FitSettings& s, Dataset* d, std::string* error,
                    bool campaigns = false);

// The flags that decide a fitting command's results (the options of
// FitSettings less --threads).
const std::vector<std::string>& ResultFlags();
// diagnose's own flags, beyond FitFlags.
const std::vector<std::string>& DiagnoseFlags();
// Their values, NAME=VALUE, with DiagnoseFlags: what a campaign's reports
// record.
std::vector<std::string> CampaignOptions();

// --output_dir: a campaign of `command` over --dataset (apps/campaign.h),
// each dataset with s.fix applied.
int Campaign(int argc, char** argv, ReportKind command, const ModalModel& model,
             const FitSettings& s, const CampaignWork& work);

// The end of an analysis of one dataset: bad input is exit 2; otherwise its
// text, its report of type R at --output, and exit 0 or 1 by its status.
template <class R, class Data, class Result>
int Finish(int argc, char** argv, const Data& d, const Result& r) {
  if (r.status.invalid_input()) return Usage(FLAGS_dataset + ": " + r.status.message);
  std::printf("%s", r.FullReport().c_str());
  if (!FLAGS_output.empty()) {
    const int rc = Write(FLAGS_output, ReportText(R{ThisRun(argc, argv, SeedFlag()), {d.name, r}}));
    if (rc != kExitOk) return rc;
  }
  return r.status.ok() ? kExitOk : kExitFailure;
}

}  // namespace ringid

#endif  // RINGID_APPS_FLAGS_H_
