// The report of extract (operations/extract.h, report/extract_report.h).
#include "operations/extract.h"

#include <complex>
#include <utility>

namespace ringid {
namespace {

// The measured functions of `c` on the lines pLSCF used against LSFD's H at
// the physical poles (LsfdFunction::At).
std::vector<FrfFit> Synthesised(const ExtractedCondition& c) {
  const PlscfResult& r = c.plscf;
  std::vector<FrfFit> fits;
  if (r.functions.size() != c.frf.functions.size()) return fits;  // the extraction failed
  std::vector<std::complex<double>> poles;
  for (const ExtractedMode& m : r.modes) poles.push_back(m.eigenvalue);
  for (size_t k = 0; k < c.frf.functions.size(); ++k) {
    const FrfFunction& fn = c.frf.functions[k];
    FrfFit f;  // its condition is the report's entry
    f.output = c.frf.outputs[fn.output].name;
    f.input = c.frf.inputs[fn.input].name;
    std::vector<std::complex<double>> measured, model;
    for (int line : r.lines) {
      const double hz = c.frf.frequencies_hz[line];
      measured.push_back(fn.h[line]);
      model.push_back(r.functions[k].At(hz, poles, r.real_poles));
      f.frequency_hz.push_back(hz);
      f.sigma.push_back(fn.sigma[line]);
      f.chi2 += std::norm((model.back() - measured.back()) / fn.sigma[line]);
      f.measured_re.push_back(measured.back().real());
      f.measured_im.push_back(measured.back().imag());
      f.model_re.push_back(model.back().real());
      f.model_im.push_back(model.back().imag());
    }
    f.frac = Frac(measured, model);
    fits.push_back(std::move(f));
  }
  return fits;
}

}  // namespace

ExtractCondition ExtractConditionOf(const ExtractedCondition& c, std::optional<std::string> name) {
  ExtractCondition e;
  e.condition = c.condition;
  e.name = std::move(name);
  e.status = c.plscf.status;
  for (const PlscfBlock& b : c.plscf.blocks) {
    ExtractBlock block;
    for (int i : b.inputs) block.inputs.push_back(c.frf.inputs[i].name);
    for (int o : b.outputs) block.outputs.push_back(c.frf.outputs[o].name);
    for (const PlscfOrder& o : b.diagram) {
      DiagramOrder order{o.order, {}};
      for (const PlscfPole& p : o.poles) {
        order.poles.push_back({p.frequency_hz, p.damping_ratio, p.stable_frequency,
                               p.stable_damping, p.stable_vector});
      }
      block.diagram.push_back(std::move(order));
    }
    e.blocks.push_back(std::move(block));
  }
  e.real_poles_per_s = c.plscf.real_poles;
  e.functions = Synthesised(c);
  return e;
}

ExtractBody ExtractBodyOf(const ExtractResult& x, const std::string& source) {
  ExtractBody b;
  b.dataset = source;
  b.status = Status::Success(std::to_string(x.poles.size()) + " physical poles, " +
                             std::to_string(x.dataset.modes.size()) + " kept as modes");
  b.poles = x.poles;
  b.notes = x.notes;
  b.routes = x.routes;
  for (const ExtractedCondition& c : x.conditions) {
    b.conditions.push_back(ExtractConditionOf(
        c, x.dataset.NamesConditions() ? std::optional<std::string>(x.dataset.conditions[c.condition].name)
                                       : std::nullopt));
  }
  return b;
}

}  // namespace ringid
