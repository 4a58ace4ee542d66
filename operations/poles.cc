// poles (operations/poles.h).
#include "operations/poles.h"

#include <cmath>
#include <utility>

#include "datasets/dataset.h"
#include "datasets/uff.h"
#include "datasets/uff_dataset.h"
#include "datasets/uff_frf.h"
#include "datasets/uff_raw_frf.h"
#include "operations/extract.h"

namespace ringid {
namespace {

// One condition's FRFs as read, before the poles.
struct Source {
  std::string name;
  Frf frf;
  std::string units;
};

bool ParseBand(const NumberList& band, PolesOptions* o, InputError* error) {
  if (band.values.empty()) return true;
  if (band.values.size() != 2) {
    *error = InputError::Option("--band: LO,HI in Hz");
    return false;
  }
  o->band_low_hz = band.values[0];
  o->band_high_hz = band.values[1];
  std::string why;
  if (!o->IsValid(&why)) {
    *error = InputError::Option("--band: " + why);
    return false;
  }
  return true;
}

bool ReadSources(const PolesInputs& in, const std::string& units, std::vector<Source>* sources,
                 std::vector<std::string>* notes, InputError* error) {
  LoadError load;
  if (!in.dataset.empty()) {
    Dataset d;
    if (!LoadDataset(in.dataset, &d, &load)) {
      *error = InputError::Of(load);
      return false;
    }
    for (size_t c = 0; c < d.conditions.size(); ++c) {
      if (!d.conditions[c].frf) continue;
      sources->push_back({d.NamesConditions() ? d.conditions[c].name : "condition " + std::to_string(c),
                          *d.conditions[c].frf, "SI (contract §9)"});
    }
    if (sources->empty()) {
      *error = {in.dataset + ": conditions: no frf block: poles need FRFs", in.dataset, "conditions",
                "no frf block: poles need FRFs"};
      return false;
    }
    return true;
  }
  UffFile file;
  if (!LoadUff(in.uff, &file, &load)) {
    *error = InputError::Of(load);
    return false;
  }
  UffMap map;
  if (!in.map.empty() && !LoadUffMap(in.map, &map, &load)) {
    *error = InputError::Of(load);
    return false;
  }
  if (!units.empty()) {
    const size_t comma = units.find(',');
    if (comma == std::string::npos) {
      *error = InputError::Option("--units: '" + units + "' is not RESPONSE,REFERENCE (e.g. g,N)");
      return false;
    }
    const std::string response = units.substr(0, comma);
    const std::string reference = comma == std::string::npos ? "" : units.substr(comma + 1);
    for (const auto& [unit, force] : {std::pair{response, false}, std::pair{reference, true}}) {
      const std::string problem = UffUnitProblem(unit, force);
      if (!problem.empty()) {
        *error = InputError::Option("--units: RESPONSE,REFERENCE: " + problem);
        return false;
      }
    }
    map.response_unit = response;
    map.reference_unit = reference;
  }
  UffRawFrfs raw;
  const bool mapped = !in.map.empty() || !units.empty();
  if (!ReadUffRawFrfs(file, mapped ? &map : nullptr, kMinPoleLines, &raw, &load)) {
    *error = InputError::Of(load);
    return false;
  }
  for (size_t c = 0; c < raw.conditions.size(); ++c) {
    sources->push_back({raw.conditions.size() == 1 ? "lines" : "lines_" + std::to_string(c + 1),
                        std::move(raw.conditions[c].frf), raw.conditions[c].units});
  }
  *notes = std::move(raw.notes);
  return true;
}

// Pole m of `found` as POLES.json has it, residues and shape on the file's
// sides (transposed back).
FoundPole PoleOf(const FoundPoles& found, size_t m, int condition) {
  const ExtractedMode& mode = found.plscf.modes[m];
  const Frf& f = found.fitted;
  FoundPole p;
  p.condition = condition;
  p.frequency_hz = mode.frequency_hz;
  p.damping_ratio = mode.damping_ratio;
  if (std::isfinite(mode.frequency_std_hz)) p.frequency_sigma_hz = mode.frequency_std_hz;
  if (std::isfinite(mode.damping_ratio_std)) p.damping_sigma = mode.damping_ratio_std;
  p.stable_orders = mode.stable_orders;
  for (const FrfFunction& fn : f.functions) {
    const std::complex<double> r = mode.residues(fn.output, fn.input);
    const std::string& out = f.outputs[fn.output].name;
    const std::string& in = f.inputs[fn.input].name;
    p.residues.push_back({found.transposed ? in : out, found.transposed ? out : in, r.real(), r.imag()});
  }
  p.shape_over = found.transposed ? "references" : "responses";
  Eigen::Index top = 0;
  if (mode.shape.size() > 0) mode.shape.cwiseAbs().maxCoeff(&top);
  const std::complex<double> phase =
      mode.shape.size() > 0 && std::abs(mode.shape(top)) > 0 ? std::abs(mode.shape(top)) / mode.shape(top) : 1.0;
  for (Eigen::Index k = 0; k < mode.shape.size(); ++k) {
    const std::complex<double> v = mode.shape(k) * phase;
    p.shape.push_back({f.outputs[k].name, v.real(), v.imag()});
  }
  return p;
}

}  // namespace

bool FindFilePoles(const PolesInputs& in, const PolesSettings& s, PolesRun* out, InputError* error) {
  *out = PolesRun{};
  if (in.uff.empty() == in.dataset.empty()) {
    *error = InputError::Option("poles needs --uff=FILE or --dataset=FILE (one of them)");
    return false;
  }
  if (!in.map.empty() && in.uff.empty()) {
    *error = InputError::Option("--map: goes with --uff");
    return false;
  }
  PolesOptions o;
  if (!ParseBand(s.band, &o, error)) return false;
  std::vector<Source> sources;
  PolesFile& file = out->file;
  file.source = in.uff.empty() ? in.dataset : in.uff;
  if (!in.dataset.empty() && !s.units.empty()) {
    *error = InputError::Option("--units: goes with --uff (a dataset's FRFs are in SI)");
    return false;
  }
  if (!ReadSources(in, s.units, &sources, &file.notes, error)) return false;
  out->body.dataset = file.source;
  for (size_t c = 0; c < sources.size(); ++c) {
    FoundPoles found;
    FindPoles(sources[c].frf, o, &found);
    if (found.status.invalid_input()) {
      *error = {file.source + ": " + sources[c].name + ": " + found.status.message, file.source,
                sources[c].name, found.status.message};
      return false;
    }
    PolesCondition pc;
    pc.name = sources[c].name;
    pc.functions = static_cast<int>(sources[c].frf.functions.size());
    pc.lines = static_cast<int>(found.plscf.lines.size());
    if (!found.plscf.lines.empty()) {
      pc.low_hz = found.fitted.frequencies_hz[found.plscf.lines.front()];
      pc.high_hz = found.fitted.frequencies_hz[found.plscf.lines.back()];
    }
    pc.units = sources[c].units;
    pc.noise = found.noise_from_residuals ? "from the residuals" : "given";
    pc.max_order = found.max_order;
    file.conditions.push_back(pc);
    if (!found.status.ok()) {
      out->body.status = Status::Failed(sources[c].name + ": " + found.status.message);
      *error = {file.source + ": " + sources[c].name + ": " + found.status.message, file.source,
                sources[c].name, found.status.message};
      return false;
    }
    for (size_t m = 0; m < found.plscf.modes.size(); ++m) {
      file.poles.push_back(PoleOf(found, m, static_cast<int>(c)));
    }
    if (found.plscf.modes.empty()) {
      file.notes.push_back(sources[c].name + ": no physical pole: no cluster of poles stable across " +
                           std::to_string(PlscfOptions{}.min_stable_orders) + " orders in the band");
    }
    out->body.conditions.push_back(
        ExtractConditionOf({static_cast<int>(c), found.fitted, found.plscf}, sources[c].name));
  }
  out->body.status = Status::Success(std::to_string(file.poles.size()) + " physical poles in " +
                                     std::to_string(file.conditions.size()) + " condition(s)");
  out->body.poles = file;
  return true;
}

}  // namespace ringid
