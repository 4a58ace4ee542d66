// The rigid-ring values a full MF-Tyre/MF-Swift property file determines
// beyond its belt block (docs/tir.md, "Contact values from a full file"): the
// contact's slip stiffnesses, relaxation lengths, radii, trail and residual
// vertical stiffness at a load F_cz0, from the Magic Formula coefficients at
// zero slip, camber and speed and the file's inflation pressure.
#ifndef RINGID_DATASETS_TIR_CONTACT_H_
#define RINGID_DATASETS_TIR_CONTACT_H_

#include <map>
#include <string>
#include <vector>

#include "datasets/dataset.h"
#include "datasets/tir.h"
#include "model/parameters.h"

namespace ringid {

// One value derived, and from what.
struct TirDerived {
  Param parameter;
  double value = 0;
  std::string from;  // the keys and the formula, with its equation
};

struct TirContact {
  std::string version;  // "6.2", "6.1" or "5.x", from [MODEL] FITTYP
  double load = 0;      // F_cz0 the values hold at (N)
  std::string summary;  // "contact values of MF 6.2 at F_cz0 = 4000 N, ..." ("" when none)
  std::vector<TirDerived> derived;  // in the order derived
  // What was not derived and why; what holds at the nominal load and speed only.
  std::vector<std::string> notes;
};

// The sections the rigid-ring mapping reads (upper case): read strictly,
// the rest of a file leniently (ParseTir).
const std::vector<std::string>& TirSectionsRead();

// The contact values `file` determines, with `belt` what TirToParameters
// read and `given` the values given by hand: a value given is not derived and
// later values use it; the load is given F_cz0, else FNOMIN. A value whose
// keys are absent, or which comes out non-positive, is left out with a note.
// False, with `error` naming the key, where a key read is not a number, a
// load, pressure, radius or stiffness the law needs is not positive, or the
// vertical law has no solution.
bool DeriveTirContact(const TirFile& file, const Parameters& belt,
                      const std::map<Param, double>& given, TirContact* contact,
                      LoadError* error);

}  // namespace ringid

#endif  // RINGID_DATASETS_TIR_CONTACT_H_
