#include "apps/reference_doc.h"

#include <cstdio>
#include <sstream>

#include "datasets/synthetic.h"
#include "model/effects.h"
#include "model/names.h"
#include "model/parameters.h"

namespace ringid {
namespace {

const char* DomainText(Domain d) {
  switch (d) {
    case Domain::kPositive: return "> 0";
    case Domain::kNonNegative: return ">= 0";
    case Domain::kReal: return "any sign";
    case Domain::kAboveOne: return "> 1";
  }
  return "";
}

const char* GroupText(Group g) {
  switch (g) {
    case Group::kInertia: return "inertia and load";
    case Group::kInPlane: return "in-plane";
    case Group::kOutOfPlane: return "out-of-plane";
    case Group::kEffect: return "effect";
    case Group::kEnvelope: return "obstacle (tandem cam)";
  }
  return "";
}

// A value to four significant digits.
std::string Significant4(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

}  // namespace

std::string ReferenceMarkdown() {
  std::ostringstream o;
  o << "# Names and units\n\n"
       "Made by `ringid reference` from the library's own tables; a test keeps this file equal\n"
       "to its output. The meaning of each name, the modal-data conventions and the dataset\n"
       "formats are in [conventions.md](conventions.md); the equations in [model.md](model.md).\n"
       "SI units throughout; frequencies in Hz.\n\n";
  const Parameters car = ExampleCarTire();
  o << "## Parameters\n\n"
       "The typical value is the example passenger car tire (`datasets/examples/car_tire.json`:\n"
       "the belt and the tandem cam of the public MF-Swift 205/60R15 example, typical contact\n"
       "values), which passes every plausibility rule of [plausibility.md](plausibility.md).\n"
       "Effect parameters are 0 in the baseline model. The tandem cam's are read only where the\n"
       "tire rolls over an obstacle (contract §11).\n\n"
       "| name | meaning | unit | sign | group | typical (car tire) |\n"
       "| --- | --- | --- | --- | --- | --- |\n";
  for (int i = 0; i < kNumParams; ++i) {
    const Param p = ParamAt(i);
    const ParameterInfo& info = Info(p);
    const bool set = car.IsSet(p) && (info.group != Group::kEffect || car[p] != 0);
    o << "| `" << ParamName(p) << "` | " << info.description << " | " << (*info.unit ? info.unit : "—") << " | "
      << DomainText(info.domain) << " | " << GroupText(info.group) << " | "
      << (set ? Significant4(car[p]) : "—") << " |\n";
  }
  o << "\n## Degrees of freedom\n\n"
       "Mode shapes name these (a dataset's `shape`, a report's shapes).\n\n"
       "| name | plane |\n| --- | --- |\n";
  for (int i = 0; i < kNumDofs; ++i) {
    const Dof d = static_cast<Dof>(i);
    bool hub = true;
    for (int l = 0; l < kNumLabels; ++l) {
      if (LabelHome(static_cast<ModeLabel>(l)) == d) hub = LabelPlane(static_cast<ModeLabel>(l)) == Plane::kHub;
    }
    o << "| `" << DofName(d) << "` | " << (hub ? "hub (with the hub_compliance effect)" : "belt or rim")
      << " |\n";
  }
  o << "\n## Mode labels\n\n"
       "A dataset's `label`; `plane` must agree. The home degree of freedom is where the mode's\n"
       "motion is largest in a typical tire; labels themselves come from strain energy\n"
       "(conventions.md §2, model.md section 9). The hub labels come from the hub_compliance effect and\n"
       "appear in model output only; a dataset that names them is refused.\n\n"
       "| label | plane | home degree of freedom |\n| --- | --- | --- |\n";
  for (int l = 0; l < kNumLabels; ++l) {
    const ModeLabel label = static_cast<ModeLabel>(l);
    o << "| `" << LabelName(label) << "` | " << ToString(LabelPlane(label)) << " | `"
      << DofName(LabelHome(label)) << "` |\n";
  }
  o << "\n## Effects\n\n"
       "`--effects=NAME,...` adds them to the model; `diagnose` tries each. The size parameter\n"
       "at 0 gives the baseline model. What each one models: conventions.md §4.\n\n"
       "| effect | parameters | size |\n| --- | --- | --- |\n";
  for (const Effect* e : EffectCatalogue()) {
    o << "| `" << e->name() << "` | ";
    const auto params = e->parameters();
    for (size_t i = 0; i < params.size(); ++i) {
      o << (i ? ", " : "") << "`" << ParamName(params[i]) << "` (" << Info(params[i]).unit << ")";
    }
    o << " | `" << ParamName(e->size()) << "` |\n";
  }
  return o.str();
}

}  // namespace ringid
