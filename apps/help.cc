#include "apps/help.h"

#include <utility>
#include <vector>

#include "estimation/fit.h"
#include "estimation/residuals.h"
#include "model/effects.h"
#include "validation/suites.h"

namespace ringid {
namespace {

// {METHODS}, {WEIGHTINGS}, {CONVENTIONS}, {DERIVATIVES}, {SUITES} and {EFFECTS} are filled in
// by Help() from the names the library defines.
const char kHelp[] =
    "ringid: identify rigid-ring (SWIFT) tire parameters from modal test data\n"
    "\n"
    "usage: ringid COMMAND [--flag=value ...]\n"
    "\n"
    "commands:\n"
    "  help       this text\n"
    "  predict    modes of a parameter set, as a table and JSON\n"
    "             --parameters=FILE | --dataset=FILE  [--effects=LIST] [--output=FILE]\n"
    "  identify   fit parameters to a dataset, with covariance and identifiability\n"
    "             --dataset=FILE [--method={METHODS}] [--starts=N] [--seed=N]\n"
    "             [--weighting={WEIGHTINGS}] [--relative_sigma=X] [--shapes=BOOL]\n"
    "             [--damping=BOOL] [--shape_convention={CONVENTIONS}]\n"
    "             [--derivatives={DERIVATIVES}] [--bounds=NAME:LO:HI,...] [--fix=NAME,...]\n"
    "             [--effects=LIST] [--output=FILE] [--save_parameters=FILE]\n"
    "  identifiability  what the data determine at the fitted point: rank,\n"
    "             classes, Wald and profile intervals, free combinations,\n"
    "             collinear pairs, identifiable subset, experiment advice\n"
    "             --dataset=FILE and the fitting flags of identify\n"
    "  compare    Downhill Simplex and Levenberg-Marquardt from the same --starts=N\n"
    "             starts: success rate, final costs, evaluations, time per fit\n"
    "             --dataset=FILE and the fitting flags of identify\n"
    "  simulate   a dataset measured from a parameter set, optionally with effects,\n"
    "             and a separate truth file\n"
    "             --parameters=FILE [--effects=LIST] [--set=NAME=VALUE,...]\n"
    "             [--frequency_noise=X] [--damping_noise=X] [--shape_noise=X]\n"
    "             [--shift=X] [--prior_spread=X] [--seed=N] --output=DATASET --truth=FILE\n"
    "             [--speeds=V,...] [--loads=F,...]: one condition per speed (m/s; 0 is\n"
    "             standing, the default) and load (N, then F_cz0 per condition);\n"
    "             several conditions or loads give a format-2 dataset\n"
    "  diagnose   the gap between the calibrated baseline and the data: where it\n"
    "             lies, which effect explains it, how far it shrinks; --effects=LIST\n"
    "             puts effects in the baseline, and the others are tried on top\n"
    "             --dataset=FILE and the fitting flags of identify\n"
    "  campaigns: identify and diagnose take --dataset=FILE,DIR,... (a directory\n"
    "             stands for its *.json) with --output_dir=DIR [--jobs=N] [--shard=I/N];\n"
    "             one report per dataset in DIR, a summary table and DIR/campaign.json\n"
    "             (campaign.I-of-N.json for a shard)\n"
    "  bench      accuracy and conditioning suites, run from the repository root\n"
    "             --suite={SUITES} [--replicates=N] [--seed=N] [--derivatives={DERIVATIVES}]\n"
    "             [--output=FILE.json] [--markdown=FILE.md]\n"
    "  schema     every report's fields and their types, as Markdown (docs/reports.md)\n"
    "  reference  parameters, degrees of freedom, labels and effects with their units,\n"
    "             as Markdown (docs/reference.md)\n"
    "  report     any JSON report of ringid as one self-contained HTML page: tables\n"
    "             and figures (SVG drawn by gnuplot, package gnuplot-nox)\n"
    "             --input=REPORT.json --output=FILE.html [--figures_dir=DIR]\n"
    "\n"
    "effects: {EFFECTS}\n"
    "\n"
    "exit status:\n"
    "  0  success\n"
    "  1  the run finished but the analysis failed (the report says why)\n"
    "  2  bad input: unreadable or malformed file, unknown or bad flag,\n"
    "     unwritable --output; one line on stderr, nothing written\n";

// `names` joined by `separator`.
std::string Joined(const std::vector<std::string>& names, const char* separator) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : separator) + n;
  return out;
}

template <class E>
std::string Alternatives() {
  const auto& names = EnumNames<E>::kNames;
  return Joined(std::vector<std::string>(names.begin(), names.end()), "|");
}

}  // namespace

std::string Help() {
  std::string help = kHelp;
  std::vector<std::string> suites;
  for (const SuiteEntry& s : Suites()) suites.push_back(s.name);
  const std::pair<const char*, std::string> fills[] = {
      {"{METHODS}", Alternatives<Method>()},
      {"{WEIGHTINGS}", Alternatives<FrequencyWeighting>()},
      {"{CONVENTIONS}", Alternatives<ShapeConvention>()},
      {"{DERIVATIVES}", Alternatives<Derivatives>()},
      {"{SUITES}", Joined(suites, "|")},
      {"{EFFECTS}", Joined(EffectNames(EffectCatalogue()), ", ")}};
  for (const auto& [key, value] : fills) help.replace(help.find(key), std::string(key).size(), value);
  return help;
}

}  // namespace ringid
