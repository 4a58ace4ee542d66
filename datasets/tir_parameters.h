// The rigid-ring part of an MF-Swift tire property file (.tir) and the
// parameters of the model (docs/tir.md). One table, TirFields(), says for each
// key how it is written from the parameters, what reading it back sets, and
// on what assumption; export, import, the header comments of a written file
// and the tables of docs/tir.md (TirMappingMarkdown, kept equal by a test)
// all come from it.
#ifndef RINGID_DATASETS_TIR_PARAMETERS_H_
#define RINGID_DATASETS_TIR_PARAMETERS_H_

#include <map>
#include <string>
#include <vector>

#include "datasets/dataset.h"
#include "datasets/tir.h"
#include "model/parameters.h"

namespace ringid {

// A key of [UNITS]: written with its SI value, and a file read must give that
// value or another spelling of it (without regard to case) where it gives the key.
struct TirUnit {
  const char* key;
  const char* si;
  std::vector<const char*> also;  // other spellings of the SI unit read
  bool required;                  // reading refuses a file without it
};
const std::vector<TirUnit>& TirUnits();

// One numeric key of the rigid-ring part.
struct TirField {
  const char* section;      // "STRUCTURAL"
  const char* key;          // "FREQ_LONG"
  const char* unit;         // SI
  const char* meaning;      // the key's meaning in MF-Swift's own words
  std::string written;      // how export computes it from the parameters
  std::string read;         // what import sets from it; "not read: WHY" when nothing
  const char* assumption;   // what the mapping assumes; "" when nothing
  bool required;            // import refuses a file without it
  std::vector<Param> inputs;  // the parameters `write` reads
  std::vector<Param> sets;    // the parameters `read_into` sets (empty: not read)
  double (*write)(const Parameters& p);
  // Sets `sets` from the key's value and what the rows before it set.
  void (*read_into)(double value, Parameters* p);
};
// In the order import reads them (a row reads only what rows before it set).
const std::vector<TirField>& TirFields();

// A key tire tools know in these sections that export does not write.
struct TirNotWritten {
  const char* section;
  const char* key;
  const char* why;
};
const std::vector<TirNotWritten>& TirKeysNotWritten();

// The parameters of the standing model (no effects) that no key sets when
// read back: what a .tir cannot hold.
std::vector<Param> ParametersNotHeldByTir();
// The key whose reading sets `p`, "[STRUCTURAL] DAMP_LONG"; "" when none.
std::string TirKeyFor(Param p);

// The .tir text of the rigid-ring part of `p`, with a `$` header naming
// `name` and `source`, what the file cannot hold (with its values) and where
// `p` breaks an assumption of the format. A key whose parameters are not all
// set is left out and named in the header; a required key cannot be: false
// then, with `error` naming the parameter (file `source`).
// `undetermined` values are marked in the header, with the keys written
// from them.
bool ParametersToTir(const Parameters& p, const std::string& name, const std::string& source,
                     std::string* text, LoadError* error,
                     const Undetermined& undetermined = {});

// The parameters the rigid-ring part of `file` determines (TirFields' `sets`);
// every other parameter is left unset. Sections and keys it does not use are
// ignored. False with `error` naming the key on a file without a belt block
// (said first), a missing required key, a unit that is not SI, a value that is
// not a positive number, or one whose parameters would not be positive
// finite numbers.
bool TirToParameters(const TirFile& file, Parameters* p, LoadError* error);

// Whether `path` names a .tir file (its extension, without regard to case).
bool IsTirPath(const std::string& path);
// A parameter set from `path` with the values `set` gives by hand applied:
// a .tir (IsTirPath) through TirToParameters and, from a full file, the
// contact values (DeriveTirContact, at set's F_cz0 or FNOMIN); set's I_ay is
// then the rim's own, and the tire's IYY - BELT_IYY is added. Anything else
// as ringid-parameters/1 JSON (LoadParameterSet). `notes` gets where values
// came from and what holds only at the nominal load. With `undetermined`, as
// LoadParameterSet less what `set` gives; a .tir says nothing of it.
bool LoadParameters(const std::string& path, const std::map<Param, double>& set, Parameters* p,
                    LoadError* error, std::vector<std::string>* notes = nullptr,
                    Undetermined* undetermined = nullptr);

// docs/tir.md's generated part: the mapping table, the keys not written and
// the parameters not held, as Markdown.
std::string TirMappingMarkdown();

}  // namespace ringid

#endif  // RINGID_DATASETS_TIR_PARAMETERS_H_
