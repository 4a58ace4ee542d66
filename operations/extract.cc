#include "operations/extract.h"

namespace ringid {

bool ExtractDataset(const std::string& path, const ExtractSettings& s, ExtractResult* out,
                    InputError* error, const Parameters* guess) {
  Dataset d;
  LoadError load;
  if (!LoadDataset(path, &d, &load)) {
    *error = InputError::Of(load);
    return false;
  }
  return ExtractDataset(d, path, s, out, error, guess);
}

bool ExtractDataset(const Dataset& given, const std::string& path, const ExtractSettings& s,
                    ExtractResult* out, InputError* error, const Parameters* guess) {
  Dataset d = given;
  if (guess) {
    for (auto& [q, v] : d.initial) {
      if (guess->IsSet(q)) v = (*guess)[q];
    }
  }
  PlscfOptions plscf;
  plscf.max_order = s.max_model_order;
  std::string why;
  if (!plscf.IsValid(&why)) {
    *error = InputError::Option("--max_model_order: " + why);
    out->status = Status::InvalidInput(error->line);
    return false;
  }
  ExtractModalDataset(RigidRingModel(), d, plscf, out);  // the options' own checks above
  if (out->status.ok()) return true;
  const std::string& m = out->status.message;
  const size_t colon = m.find(": ");
  *error = {path + ": " + m, path, colon == std::string::npos ? "" : m.substr(0, colon), m};
  return false;
}

}  // namespace ringid
