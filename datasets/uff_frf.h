// A test lab's FRFs (UFF dataset 58/58b) as the frf blocks of format-3
// conditions (contract §9, docs/uff.md). A map (ringid-uff-map/2) places
// each node on the belt or the rim (`points`); a function's response and
// reference directions (1, 2, 3: the node's x, y, z; negative: the opposite
// sense) become directions in ringid's axes through the node's displacement
// system (dataset 18) and the map's `axes`. Values become SI by the unit
// exponents of records 9 and 10 with dataset 164's factors, or by the units
// label where the exponents are 0; record 9's specific data type says what
// the response measures.
#ifndef RINGID_DATASETS_UFF_FRF_H_
#define RINGID_DATASETS_UFF_FRF_H_

#include <optional>
#include <string>
#include <vector>

#include "datasets/frf.h"
#include "datasets/uff.h"
#include "datasets/uff_dataset.h"

namespace ringid {

// Without a coherence function a line's sigma is FrfSigma at
// kDefaultFrfRelativeSigma (datasets/frf.h). The import says so; χ² is then no
// test of the data's noise.
// A coherence outside (0, 1) (1 to the file's precision, 0 at a line with no
// coherent power) is taken as the nearer of these, and the function's sigma
// written out (the loader takes coherence only inside (0, 1)).
inline constexpr double kUffMinCoherence = 0.01;
inline constexpr double kUffMaxCoherence = 1 - 1e-6;

// A unit a function's units label or the map's `units` may name.
struct UffUnitName {
  const char* name;
  std::optional<FrfQuantity> quantity;  // empty: a force
  double si;                            // the unit in SI (m, m/s, m/s², N)
};
const std::vector<UffUnitName>& UffUnitNames();
// Why `name` is not a unit of the kind asked (a force, or a motion), with the
// nearest name; empty if it is one.
std::string UffUnitProblem(const std::string& name, bool force);

// Adds the FRFs (function type 4) of `file` under `map` to out->dataset as
// standing conditions of format 3: the functions on the lines of the first
// join condition 0 (with the modes, if any), each other set of lines a
// condition of its own. A coherence function (type 6) of the same pair and
// lines gives sigma with map.averages. Functions the map cannot place and
// other function types are listed in out->notes and left out. False, with
// `error` naming the UFF record or the map's field, where a function's units
// or lines cannot be read, a placed node cannot be located, or no function
// is placed.
bool AddUffFrfs(const UffFile& file, const UffMap& map, UffImport* out, LoadError* error);

// "dataset 58 #3 (line 120)": function k of the file as the reader names it.
std::string UffFunctionName(const UffFile& file, size_t k);
// "101:+3": a node and direction as `import --uff` lists them.
std::string UffNodeName(int node, int direction);

// What a response of record 9's specific data type measures: displacement
// (8), velocity (11), acceleration (12); empty for any other.
std::optional<FrfQuantity> UffResponseQuantity(int specific_data_type);

// The factor that takes FRF `k` of `file` (function type 4) to SI and what
// its response measures, by the map's units or the file's, as AddUffFrfs
// reads them; false with `why` naming the record where they do not say.
bool UffFrfUnits(const UffFile& file, size_t k, const UffMap& map, double* si,
                 FrfQuantity* quantity, std::string* said, LoadError* why);

}  // namespace ringid

#endif  // RINGID_DATASETS_UFF_FRF_H_
