#include "datasets/tir_parameters.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <set>

#include "datasets/file_kind.h"
#include "datasets/tir_contact.h"
#include "model/rigid_ring_model.h"

namespace ringid {
namespace {

using P = Param;

// FREQ_* and DAMP_* hold the undamped frequency and the damping ratio of a
// sidewall element (model/parameters.h), named by its stiffness or damper.
const SidewallElement& Element(Param p) { return *SidewallOf(p); }
double Frequency(const Parameters& p, Param k) { return SidewallFrequencyHz(Element(k), p); }
double Ratio(const Parameters& p, Param c) { return SidewallDampingRatio(Element(c), p); }
// Each stiffness of `ks` (damper of `cs`) set to give its element frequency
// (ratio) v.
void SetFrequency(double v, std::initializer_list<Param> ks, Parameters* p) {
  for (Param k : ks) (*p)[k] = SidewallStiffness(Element(k), v, *p);
}
void SetRatio(double v, std::initializer_list<Param> cs, Parameters* p) {
  for (Param c : cs) (*p)[c] = SidewallDamper(Element(c), v, *p);
}
// What the frequency (ratio) of an element reads.
std::vector<Param> FrequencyInputs(Param k) { return {k, Element(k).inertia}; }
std::vector<Param> RatioInputs(Param c) { return {c, Element(c).stiffness, Element(c).inertia}; }

std::string Name(Param p) { return ParamName(p); }
// "sqrt(k_bx / m_b) / (2 pi)", "c_bx / (2 sqrt(k_bx m_b))".
std::string FrequencyText(Param k) {
  return "sqrt(" + Name(k) + " / " + Name(Element(k).inertia) + ") / (2 pi)";
}
std::string RatioText(Param c) {
  const SidewallElement& e = Element(c);
  return Name(c) + " / (2 sqrt(" + Name(e.stiffness) + " " + Name(e.inertia) + "))";
}
// What reading `key` sets, each parameter from its own element, those with
// the same formula together: "k_bx = k_bz = m_b (2 pi FREQ_LONG)^2".
std::string SetsText(const std::vector<std::pair<Param, std::string>>& sets) {
  std::string out;
  for (size_t i = 0; i < sets.size(); ++i) {
    out += Name(sets[i].first) + " = ";
    if (i + 1 < sets.size() && sets[i + 1].second == sets[i].second) continue;
    out += sets[i].second + (i + 1 < sets.size() ? ", " : "");
  }
  return out;
}
std::string FromFrequencyText(const std::string& key, std::initializer_list<Param> ks) {
  std::vector<std::pair<Param, std::string>> sets;
  for (Param k : ks) sets.push_back({k, Name(Element(k).inertia) + " (2 pi " + key + ")^2"});
  return SetsText(sets);
}
std::string FromRatioText(const std::string& key, std::initializer_list<Param> cs) {
  std::vector<std::pair<Param, std::string>> sets;
  for (Param c : cs) {
    const SidewallElement& e = Element(c);
    sets.push_back({c, "2 " + key + " sqrt(" + Name(e.stiffness) + " " + Name(e.inertia) + ")"});
  }
  return SetsText(sets);
}

}  // namespace

const std::vector<TirUnit>& TirUnits() {
  static const std::vector<TirUnit> units = {
      {"LENGTH", "meter", {"metre", "m"}, true},
      {"FORCE", "newton", {"n"}, true},
      {"ANGLE", "radians", {"radian", "rad"}, false},
      {"MASS", "kg", {"kilogram"}, true},
      {"TIME", "second", {"seconds", "sec", "s"}, true},
  };
  return units;
}

const std::vector<TirField>& TirFields() {  // size-check: data table
  static const std::vector<TirField> fields = {
      {"INERTIA", "BELT_MASS", "kg", "Belt mass", "m_b", "m_b = BELT_MASS", "", true,
       {P::m_b}, {P::m_b},
       [](const Parameters& p) { return p[P::m_b]; },
       [](double v, Parameters* p) { (*p)[P::m_b] = v; }},
      {"INERTIA", "BELT_IXX", "kg m^2", "Belt diametral moment of inertia", "I_bx",
       "I_bx = I_bz = BELT_IXX",
       "the belt is a ring: its inertias about x (camber) and z (yaw) are equal; where I_bz "
       "differs, BELT_IXX holds I_bx and the header gives I_bz",
       true, {P::I_bx}, {P::I_bx, P::I_bz},
       [](const Parameters& p) { return p[P::I_bx]; },
       [](double v, Parameters* p) { (*p)[P::I_bx] = (*p)[P::I_bz] = v; }},
      {"INERTIA", "BELT_IYY", "kg m^2", "Belt polar moment of inertia", "I_by", "I_by = BELT_IYY",
       "", true, {P::I_by}, {P::I_by},
       [](const Parameters& p) { return p[P::I_by]; },
       [](double v, Parameters* p) { (*p)[P::I_by] = v; }},
      {"STRUCTURAL", "LONGITUDINAL_STIFFNESS", "N/m", "Tyre overall longitudinal stiffness",
       "1 / (1/k_bx + r_e0^2/k_btheta + sigma_cx/K_cx)",
       "with a full file (docs/tir.md): sigma_cx = K_cx (1/C_x - 1/k_bx - r_e0^2/k_btheta), C_x "
       "this at F_cz0; else not read (it gives only K_cx/sigma_cx)",
       "the static force on the hub per unit longitudinal hub displacement, wheel locked "
       "(theta_a held), standing on the road: the sidewall k_bx, the sidewall torsion k_btheta "
       "through r_e0 and the contact K_cx/sigma_cx in series (the standing K of eq. (12))",
       false, {P::k_bx, P::k_btheta, P::r_e0, P::K_cx, P::sigma_cx}, {},
       [](const Parameters& p) {
         return 1 / (1 / p[P::k_bx] + p[P::r_e0] * p[P::r_e0] / p[P::k_btheta] +
                     p[P::sigma_cx] / p[P::K_cx]);
       },
       nullptr},
      {"STRUCTURAL", "LATERAL_STIFFNESS", "N/m", "Tyre overall lateral stiffness",
       "1 / (1/k_by + r_l0^2/(k_bgamma + r_l0 F_cz0) + sigma_cy/K_cy)",
       "with a full file (docs/tir.md): sigma_cy = K_cy (1/C_y - 1/k_by - r_l0^2/(k_bgamma + r_l0 "
       "F_cz0)), C_y this at F_cz0; else not read (it gives only K_cy/sigma_cy)",
       "the static force on the hub per unit lateral hub displacement, standing on the road at "
       "the load F_cz0: the sidewall k_by, the belt camber k_bgamma + r_l0 F_cz0 through r_l0 "
       "and the contact K_cy/sigma_cy in series (the standing S of eq. (15); the belt yaws but "
       "that does not act back at standstill)",
       false, {P::k_by, P::k_bgamma, P::r_l0, P::F_cz0, P::K_cy, P::sigma_cy}, {},
       [](const Parameters& p) {
         return 1 / (1 / p[P::k_by] +
                     p[P::r_l0] * p[P::r_l0] / (p[P::k_bgamma] + p[P::r_l0] * p[P::F_cz0]) +
                     p[P::sigma_cy] / p[P::K_cy]);
       },
       nullptr},
      {"STRUCTURAL", "FREQ_LONG", "Hz", "Undamped frequency fore/aft and vertical mode",
       FrequencyText(P::k_bx), FromFrequencyText("FREQ_LONG", {P::k_bx, P::k_bz}),
       "the belt on a fixed rim without road contact; one frequency fore/aft and vertical, so "
       "k_bz = k_bx (where k_bz differs, the header gives its frequency)",
       true, FrequencyInputs(P::k_bx), {P::k_bx, P::k_bz},
       [](const Parameters& p) { return Frequency(p, P::k_bx); },
       [](double v, Parameters* p) { SetFrequency(v, {P::k_bx, P::k_bz}, p); }},
      {"STRUCTURAL", "FREQ_LAT", "Hz", "Undamped frequency lateral mode",
       FrequencyText(P::k_by), FromFrequencyText("FREQ_LAT", {P::k_by}),
       "the belt on a fixed rim without road contact (no K_cy/sigma_cy)", true,
       FrequencyInputs(P::k_by), {P::k_by},
       [](const Parameters& p) { return Frequency(p, P::k_by); },
       [](double v, Parameters* p) { SetFrequency(v, {P::k_by}, p); }},
      {"STRUCTURAL", "FREQ_YAW", "Hz", "Undamped frequency yaw and camber mode",
       FrequencyText(P::k_bpsi), FromFrequencyText("FREQ_YAW", {P::k_bpsi, P::k_bgamma}),
       "the belt on a fixed rim without road contact; one frequency for yaw and camber, so "
       "sqrt(k_bgamma / I_bx) = sqrt(k_bpsi / I_bz): the camber stiffness without the road's "
       "r_l0 F_cz0 (where the camber frequency differs, the header gives it)",
       true, FrequencyInputs(P::k_bpsi), {P::k_bpsi, P::k_bgamma},
       [](const Parameters& p) { return Frequency(p, P::k_bpsi); },
       [](double v, Parameters* p) { SetFrequency(v, {P::k_bpsi, P::k_bgamma}, p); }},
      {"STRUCTURAL", "FREQ_WINDUP", "Hz", "Undamped frequency wind-up mode",
       FrequencyText(P::k_btheta), FromFrequencyText("FREQ_WINDUP", {P::k_btheta}),
       "the belt turning about y against the sidewall on a fixed rim (theta_a held), without "
       "road contact",
       true, FrequencyInputs(P::k_btheta), {P::k_btheta},
       [](const Parameters& p) { return Frequency(p, P::k_btheta); },
       [](double v, Parameters* p) { SetFrequency(v, {P::k_btheta}, p); }},
      {"STRUCTURAL", "DAMP_LONG", "-", "Dimensionless damping fore/aft and vertical mode",
       RatioText(P::c_bx), FromRatioText("DAMP_LONG", {P::c_bx, P::c_bz}),
       "as FREQ_LONG, one ratio fore/aft and vertical (where c_bz's differs, the header gives "
       "it)",
       false, RatioInputs(P::c_bx), {P::c_bx, P::c_bz},
       [](const Parameters& p) { return Ratio(p, P::c_bx); },
       [](double v, Parameters* p) { SetRatio(v, {P::c_bx, P::c_bz}, p); }},
      {"STRUCTURAL", "DAMP_LAT", "-", "Dimensionless damping lateral mode",
       RatioText(P::c_by), FromRatioText("DAMP_LAT", {P::c_by}), "", false,
       RatioInputs(P::c_by), {P::c_by},
       [](const Parameters& p) { return Ratio(p, P::c_by); },
       [](double v, Parameters* p) { SetRatio(v, {P::c_by}, p); }},
      {"STRUCTURAL", "DAMP_YAW", "-", "Dimensionless damping yaw and camber mode",
       RatioText(P::c_bpsi), FromRatioText("DAMP_YAW", {P::c_bpsi, P::c_bgamma}),
       "as FREQ_YAW, one ratio for yaw and camber (where the camber ratio differs, the header "
       "gives it)",
       false, RatioInputs(P::c_bpsi), {P::c_bpsi, P::c_bgamma},
       [](const Parameters& p) { return Ratio(p, P::c_bpsi); },
       [](double v, Parameters* p) { SetRatio(v, {P::c_bpsi, P::c_bgamma}, p); }},
      {"STRUCTURAL", "DAMP_WINDUP", "-", "Dimensionless damping wind-up mode",
       RatioText(P::c_btheta), FromRatioText("DAMP_WINDUP", {P::c_btheta}), "",
       false, RatioInputs(P::c_btheta), {P::c_btheta},
       [](const Parameters& p) { return Ratio(p, P::c_btheta); },
       [](double v, Parameters* p) { SetRatio(v, {P::c_btheta}, p); }},
      {"VERTICAL", "VERTICAL_STIFFNESS", "N/m", "Tyre vertical stiffness",
       "1 / (1/k_bz + 1/k_cz)",
       "k_cz = 1 / (1/VERTICAL_STIFFNESS - 1/k_bz), k_bz from FREQ_LONG; so it must be below "
       "k_bz. With a full file, VERTICAL_STIFFNESS is the vertical law's at F_cz0 (docs/tir.md)",
       "the static stiffness from hub to road: the load passes the sidewall k_bz (hub to belt) "
       "and then the contact's residual stiffness k_cz (belt to road), in series. Not k_bz + "
       "k_cz, which is the vertical mode's stiffness with the hub held",
       false, {P::k_bz, P::k_cz}, {P::k_cz},
       [](const Parameters& p) { return 1 / (1 / p[P::k_bz] + 1 / p[P::k_cz]); },
       [](double v, Parameters* p) { (*p)[P::k_cz] = 1 / (1 / v - 1 / (*p)[P::k_bz]); }},
  };
  return fields;
}

const std::vector<TirNotWritten>& TirKeysNotWritten() {
  static const std::vector<TirNotWritten> keys = {
      {"INERTIA", "MASS, IXX, IYY",
       "the whole tire's; ringid has the belt (BELT_*) and the rim I_ay, which a .tir does not "
       "hold"},
      {"VERTICAL", "FNOMIN",
       "the reference load of the Magic Formula coefficients, which ringid does not have; the "
       "values written are at the parameter set's F_cz0, which the header names (read, with the "
       "Magic Formula, from a full file)"},
      {"VERTICAL", "VERTICAL_DAMPING",
       "the model's contact has no damper (c_bz, the sidewall's, is in DAMP_LONG)"},
      {"STRUCTURAL", "YAW_STIFFNESS",
       "the standing model has none to give: belt yaw does not enter the contact slip at "
       "standstill (docs/model.md section 6), so the road would not resist a steered rim, and "
       "the rim has no yaw freedom; the effect contact_yaw_stiffness (k_cpsi) is the nearest"},
      {"STRUCTURAL", "DAMP_RESIDUAL, DAMP_VLOW",
       "the model has no stiffness-proportional damping"},
      {"STRUCTURAL", "Q_BVX, Q_BVT",
       "the model's sidewall stiffnesses k_b* do not change with load or speed"},
      {"STRUCTURAL", "PCFX1, PCFX2, PCFX3, PCFY1, PCFY2, PCFY3, PCMZ1",
       "the model's stiffnesses do not change with deflection or pressure"},
  };
  return keys;
}

std::vector<Param> ParametersNotHeldByTir() {
  std::set<Param> held;
  for (const TirField& f : TirFields()) held.insert(f.sets.begin(), f.sets.end());
  std::vector<Param> out;
  for (Param p : RigidRingModel().parameters()) {
    if (!held.count(p)) out.push_back(p);
  }
  return out;
}

std::string TirKeyFor(Param p) {
  for (const TirField& f : TirFields()) {
    if (std::find(f.sets.begin(), f.sets.end(), p) != f.sets.end()) {
      return std::string("[") + f.section + "] " + f.key;
    }
  }
  return "";
}

namespace {

std::string Upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// Text for a `$` comment: one line of printable ASCII.
std::string CommentText(const std::string& s) {
  std::string out;
  for (const char c : s) out += (c >= 32 && c < 127) ? c : '?';
  return out;
}

// Whether a and b differ by more than rounding.
bool Differ(double a, double b) { return std::abs(a - b) > 1e-9 * std::max(std::abs(a), std::abs(b)); }

bool AllSet(const Parameters& p, std::initializer_list<Param> qs) {
  for (Param q : qs) {
    if (!p.IsSet(q)) return false;
  }
  return true;
}

// `items` as `$` comment lines of at most about 96 characters, the first
// starting with `lead`.
void CommentList(const std::string& lead, const std::vector<std::string>& items,
                 std::string* out) {
  std::string line = "$ " + lead;
  for (size_t i = 0; i < items.size(); ++i) {
    const std::string item = items[i] + (i + 1 < items.size() ? "," : "");
    if (line.size() + 1 + item.size() > 96) {
      *out += line + "\n";
      line = "$  ";
    }
    line += " " + item;
  }
  *out += line + "\n";
}

// "KEY = value $comment", aligned as tools write it.
std::string KeyLine(const std::string& key, const std::string& value, const std::string& comment) {
  std::string line = key;
  line.resize(std::max<size_t>(line.size(), 24), ' ');
  line += " = " + value;
  if (comment.empty()) return line + "\n";
  line.resize(std::max<size_t>(line.size(), 50), ' ');
  return line + " $" + comment + "\n";
}

// "$-----...units" and "[UNITS]", as tools write a section's start.
std::string SectionHeader(const std::string& section) {
  std::string lower = section;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return "$" + std::string(70 - lower.size(), '-') + lower + "\n[" + section + "]\n";
}

// The fields of TirFields() that `p` can write, into `written`; those an
// optional parameter left unset named in `unset`. False, with `error`, where a
// required parameter is missing or a value cannot be written.
bool FieldsToWrite(const Parameters& p, std::vector<const TirField*>* written,
                   std::vector<std::string>* unset, LoadError* error) {
  for (const TirField& f : TirFields()) {
    const std::string key = std::string("[") + f.section + "] " + f.key;
    const auto missing = std::find_if(f.inputs.begin(), f.inputs.end(),
                                      [&](Param q) { return !p.IsSet(q); });
    if (missing != f.inputs.end()) {
      if (f.required) {
        error->field = std::string("parameters.") + ParamName(*missing);
        error->message = "missing (the .tir's " + key + " needs it)";
        return false;
      }
      unset->push_back(std::string(f.key) + " (" + ParamName(*missing) + ")");
      continue;
    }
    for (Param q : f.inputs) {
      if (!(p[q] > 0) || !std::isfinite(p[q])) {
        error->field = std::string("parameters.") + ParamName(q);
        error->message = "must be a positive number (for the .tir's " + key + ")";
        return false;
      }
    }
    const double v = f.write(p);
    if (!(v > 0) || !std::isfinite(v)) {
      error->field = key;
      error->message = "cannot be written: its parameters give " + TirNumber(v);
      return false;
    }
    written->push_back(&f);
  }
  return true;
}

// The header's lines where the parameters break an assumption of the
// format: what the key holds, and what it does not.
std::string AssumptionNotes(const Parameters& p) {
  std::string out;
  const auto note = [&](bool breaks, const std::string& line) {
    if (breaks) out += "$ " + line + "\n";
  };
  if (AllSet(p, {P::I_bx, P::I_bz})) {
    note(Differ(p[P::I_bx], p[P::I_bz]),
         "BELT_IXX holds I_bx; I_bz = " + TirNumber(p[P::I_bz]) +
             " kg m^2 differs and reads back as I_bx.");
  }
  if (AllSet(p, {P::k_bx, P::k_bz, P::m_b})) {
    note(Differ(p[P::k_bx], p[P::k_bz]),
         "FREQ_LONG holds k_bx; k_bz = " + TirNumber(p[P::k_bz]) + " N/m differs (its frequency " +
             TirNumber(Frequency(p, P::k_bz)) +
             " Hz) and reads back as k_bx" +
             (p.IsSet(P::k_cz) ? "; VERTICAL_STIFFNESS keeps the series of k_bz and k_cz." : "."));
  }
  if (AllSet(p, {P::k_bgamma, P::I_bx, P::k_bpsi, P::I_bz})) {
    const double camber = Frequency(p, P::k_bgamma);
    note(Differ(camber, Frequency(p, P::k_bpsi)),
         "FREQ_YAW holds the yaw " + FrequencyText(P::k_bpsi) + "; the camber frequency " +
             TirNumber(camber) + " Hz (k_bgamma = " + TirNumber(p[P::k_bgamma]) +
             " N m/rad) differs and is not held.");
  }
  if (AllSet(p, {P::c_bx, P::c_bz, P::k_bx, P::k_bz, P::m_b})) {
    const double vertical = Ratio(p, P::c_bz);
    note(Differ(vertical, Ratio(p, P::c_bx)),
         "DAMP_LONG holds c_bx; the vertical ratio " + RatioText(P::c_bz) + " = " +
             TirNumber(vertical) + " (c_bz = " + TirNumber(p[P::c_bz]) +
             " N s/m) differs and is not held.");
  }
  if (AllSet(p, {P::c_bgamma, P::c_bpsi, P::k_bgamma, P::k_bpsi, P::I_bx, P::I_bz})) {
    const double camber = Ratio(p, P::c_bgamma);
    note(Differ(camber, Ratio(p, P::c_bpsi)),
         "DAMP_YAW holds the yaw c_bpsi; the camber ratio " + RatioText(P::c_bgamma) + " = " +
             TirNumber(camber) + " (c_bgamma = " + TirNumber(p[P::c_bgamma]) +
             " N m s/rad) differs and is not held.");
  }
  return out;
}

}  // namespace

bool ParametersToTir(const Parameters& p, const std::string& name, const std::string& source,
                     std::string* text, LoadError* error, const Undetermined& undetermined) {
  error->file = source;
  error->field.clear();
  std::vector<const TirField*> written;
  std::vector<std::string> unset;
  if (!FieldsToWrite(p, &written, &unset, error)) return false;

  std::string out;
  out += "[MDI_HEADER]\n";
  out += KeyLine("FILE_TYPE", "'tir'", "");
  out += KeyLine("FILE_VERSION", "3.0", "");
  out += KeyLine("FILE_FORMAT", "'ASCII'", "");
  out += "$ ringid export: the rigid-ring (SWIFT) belt of '" + CommentText(name) + "' from " +
         CommentText(source) + "\n";
  out += "$ Only the rigid-ring part of an MF-Swift tire: merge these sections into the tire's\n";
  out += "$ full .tir. Every key, its formula and its assumption: docs/tir.md of ringid.\n";
  if (p.IsSet(P::F_cz0)) {
    out += "$ Stiffnesses are the model's at standstill at F_cz0 = " + TirNumber(p[P::F_cz0]) +
           " N; no FNOMIN is written.\n";
  }
  out += AssumptionNotes(p);
  std::vector<std::string> not_held, effects, cam;
  for (Param q : ParametersNotHeldByTir()) {
    not_held.push_back(std::string(ParamName(q)) +
                       (p.IsSet(q) ? " = " + TirNumber(p[q]) + " " + Info(q).unit : " (unset)"));
  }
  CommentList("A .tir cannot hold (ringid parameters, SI):", not_held, &out);
  // Values the data left undetermined, and the keys written from them: as
  // uncertain, whatever their digits.
  for (const auto& [q, why] : undetermined) {
    if (!p.IsSet(q)) continue;
    std::string keys;
    for (const TirField* f : written) {
      if (std::find(f->inputs.begin(), f->inputs.end(), q) == f->inputs.end()) continue;
      keys += (keys.empty() ? " in " : ", ") + std::string(f->key);
    }
    out += "$ UNDETERMINED by the data: " + std::string(ParamName(q)) + " = " + TirNumber(p[q]) +
           " " + Info(q).unit + (keys.empty() ? " (in no key)" : keys) + ": " + CommentText(why) +
           "\n";
  }
  for (int i = 0; i < kNumParams; ++i) {
    const Param q = ParamAt(i);
    if (Info(q).group == Group::kEffect && p.IsSet(q) && p[q] != 0) {
      effects.push_back(std::string(ParamName(q)) + " = " + TirNumber(p[q]) + " " + Info(q).unit);
    }
    if (Info(q).group == Group::kEnvelope && p.IsSet(q)) {
      cam.push_back(std::string(ParamName(q)) + " = " + TirNumber(p[q]) + " " + Info(q).unit);
    }
  }
  if (!effects.empty()) CommentList("Nor the effect parameters:", effects, &out);
  if (!cam.empty()) {
    CommentList("Not written, the tandem cam (ringid writes no [CONTACT_PATCH]):", cam, &out);
  }
  if (!unset.empty()) CommentList("Not written, a parameter unset:", unset, &out);
  std::vector<std::string> never;
  for (const TirNotWritten& k : TirKeysNotWritten()) never.push_back(k.key);
  CommentList("Never written (docs/tir.md says why):", never, &out);

  out += SectionHeader("UNITS");
  for (const TirUnit& u : TirUnits()) out += KeyLine(u.key, std::string("'") + u.si + "'", "");
  for (const char* section : {"INERTIA", "VERTICAL", "STRUCTURAL"}) {
    std::string lines;
    for (const TirField* f : written) {
      if (std::string(f->section) != section) continue;
      lines += KeyLine(f->key, TirNumber(f->write(p)), std::string(f->meaning) + ": " + f->written);
    }
    if (lines.empty()) continue;
    out += SectionHeader(section) + lines;
  }
  *text = out;
  return true;
}

bool TirToParameters(const TirFile& file, Parameters* p, LoadError* error) {
  *p = Parameters{};
  error->file = file.path;
  error->field.clear();
  const auto fail = [&](const std::string& field, const std::string& message) {
    error->field = field;
    error->message = message;
    return false;
  };
  if (!file.Find("INERTIA", "BELT_MASS") && !file.Find("STRUCTURAL", "FREQ_LONG")) {
    return fail("[INERTIA] BELT_MASS",
                "missing, and [STRUCTURAL] FREQ_LONG too: the file has no rigid-ring (MF-Swift "
                "belt) block, and ringid reads its model from that block" +
                std::string(std::any_of(file.entries.begin(), file.entries.end(),
                                        [](const TirEntry& e) { return Upper(e.key) == "MBELT"; })
                                ? " (MBELT is PAC2002's belt mass, not a rigid ring)"
                                : ""));
  }
  if (!file.HasSection("UNITS")) {
    return fail("[UNITS]", "missing: ringid reads SI .tir files only, and needs them to say so");
  }
  for (const TirUnit& u : TirUnits()) {
    const TirEntry* e = file.Find("UNITS", u.key);
    if (!e) {
      if (u.required) return fail(std::string("[UNITS] ") + u.key, std::string("missing (ringid reads SI .tir files only: '") + u.si + "')");
      continue;
    }
    bool si = !e->number && Upper(e->text) == Upper(u.si);
    for (const char* spelling : u.also) si = si || (!e->number && Upper(e->text) == Upper(spelling));
    if (!si) {
      return fail(e->Where(), std::string("must be '") + u.si + "' (ringid reads SI .tir files only)");
    }
  }
  for (const TirField& f : TirFields()) {
    if (!f.read_into) continue;
    const TirEntry* e = file.Find(f.section, f.key);
    if (!e) {
      if (!f.required) continue;
      std::string sets;
      for (Param q : f.sets) sets += (sets.empty() ? "" : ", ") + std::string(ParamName(q));
      return fail(std::string("[") + f.section + "] " + f.key, "missing (ringid reads " + sets + " from it)");
    }
    if (!e->number) return fail(e->Where(), "must be a number, not a quoted string");
    const double v = *e->number;
    if (!(v > 0)) return fail(e->Where(), "must be positive, not " + TirNumber(v));
    Parameters q = *p;
    f.read_into(v, &q);
    for (Param s : f.sets) {
      if (!(q[s] > 0) || !std::isnormal(q[s])) {
        return fail(e->Where(), std::string("gives ") + ParamName(s) + " = " + TirNumber(q[s]) +
                                    ", not a positive finite number (" + f.read + ")");
      }
    }
    *p = q;
  }
  return true;
}

bool IsTirPath(const std::string& path) { return SniffPath(path).kind == FileKind::kTir; }

namespace {

// The rim's inertia: `rim` (the wheel's own, given by hand) and the tire's
// part off the belt, IYY - BELT_IYY, where the file gives both.
bool RimInertia(const TirFile& file, double rim, Parameters* p, std::vector<std::string>* notes,
                LoadError* error) {
  const TirEntry* whole = file.Find("INERTIA", "IYY");
  const TirEntry* belt = file.Find("INERTIA", "BELT_IYY");
  if (!whole || !belt || !whole->number || !belt->number) {
    notes->push_back("I_ay = " + ShortNumber(rim) + " kg m^2 as given (the file has no [INERTIA] "
                     "IYY and BELT_IYY for the tire's share)");
    (*p)[Param::I_ay] = rim;
    return true;
  }
  const double share = *whole->number - *belt->number;
  if (!(share >= 0)) {
    error->field = whole->Where();
    error->message = "IYY = " + TirNumber(*whole->number) + " is below BELT_IYY = " +
                     TirNumber(*belt->number) + ": the tire's inertia must hold its belt's";
    return false;
  }
  (*p)[Param::I_ay] = rim + share;
  notes->push_back("I_ay = " + ShortNumber(rim + share) + " kg m^2: the rim's " +
                   ShortNumber(rim) + " given, plus the tire's part off the belt, IYY - BELT_IYY = " +
                   ShortNumber(share) + " (a .tir describes the tire, not the wheel)");
  return true;
}

}  // namespace

bool LoadParameters(const std::string& path, const std::map<Param, double>& set, Parameters* p,
                    LoadError* error, std::vector<std::string>* notes,
                    Undetermined* undetermined) {
  std::vector<std::string> ignored;
  if (!notes) notes = &ignored;
  notes->clear();
  if (!IsTirPath(path)) {
    if (!LoadParameterSet(path, p, error, undetermined)) return false;
    for (const auto& [q, v] : set) {
      (*p)[q] = v;
      if (undetermined) undetermined->erase(q);  // given by hand
    }
    return true;
  }
  if (undetermined) undetermined->clear();
  TirFile file;
  if (!LoadTir(path, &file, error, &TirSectionsRead()) || !TirToParameters(file, p, error)) {
    return false;
  }
  *notes = file.notes;
  TirContact contact;
  if (!DeriveTirContact(file, *p, set, &contact, error)) return false;
  for (const auto& [q, v] : set) (*p)[q] = v;
  for (const TirDerived& d : contact.derived) {
    (*p)[d.parameter] = d.value;
    notes->push_back(std::string(ParamName(d.parameter)) + " = " + ShortNumber(d.value) + " " +
                     Info(d.parameter).unit + " from " + d.from);
  }
  if (!contact.summary.empty() && !contact.derived.empty()) {
    notes->insert(notes->begin() + file.notes.size(), contact.summary);
  }
  notes->insert(notes->end(), contact.notes.begin(), contact.notes.end());
  const auto rim = set.find(Param::I_ay);
  if (rim != set.end() && !RimInertia(file, rim->second, p, notes, error)) return false;
  for (int i = 0; i < kNumParams; ++i) {  // what the keys give, against physics
    const Param q = ParamAt(i);
    const std::string problem = p->IsSet(q) ? ParameterValueProblem(q, (*p)[q]) : "";
    if (!problem.empty()) {
      error->file = path;
      error->field = ParamName(q);
      error->message = problem;
      return false;
    }
  }
  return true;
}

std::string TirMappingMarkdown() {
  std::string md;
  md += "`[UNITS]` is written as";
  std::string required;
  for (const TirUnit& u : TirUnits()) {
    md += std::string(&u == &TirUnits().front() ? " " : ", ") + "`" + u.key + " = '" + u.si + "'`";
    if (u.required) required += (required.empty() ? "" : ", ") + std::string(u.key);
  }
  std::string spellings;
  for (const TirUnit& u : TirUnits()) {
    for (const char* also : u.also) {
      spellings += (spellings.empty() ? "" : ", ") + std::string("`'") + also + "'`";
    }
  }
  md += ". A file read must give " + required +
        " with these values or another spelling of them (" + spellings +
        "; without regard to case), and ANGLE, where it gives it: ringid reads SI files only.\n\n";
  md += "| section | key | unit | meaning (MF-Swift) | written from | read back as | assumption | "
        "needed to read |\n";
  md += "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const TirField& f : TirFields()) {
    md += std::string("| `[") + f.section + "]` | `" + f.key + "` | " + f.unit + " | " +
          f.meaning + " | `" + f.written + "` | " + f.read + " | " +
          (*f.assumption ? f.assumption : "-") + " | " + (f.required ? "yes" : "no") + " |\n";
  }
  md += "\nNot written:\n\n| section | key | why |\n| --- | --- | --- |\n";
  for (const TirNotWritten& k : TirKeysNotWritten()) {
    md += std::string("| `[") + k.section + "]` | " + k.key + " | " + k.why + " |\n";
  }
  md += "\nA .tir cannot hold these parameters of the standing model (no key sets them when read "
        "back; a written file lists their values in its `$` header):";
  for (Param q : ParametersNotHeldByTir()) {
    md += std::string(q == ParametersNotHeldByTir().front() ? " " : ", ") + "`" + ParamName(q) + "`";
  }
  md += ".\n";
  return md;
}

}  // namespace ringid
