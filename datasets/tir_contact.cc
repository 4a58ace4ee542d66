#include "datasets/tir_contact.h"

#include <cmath>
#include <optional>

#include "datasets/load_failure.h"

namespace ringid {
namespace {

using internal::Captured;
using internal::Failure;  // caught in DeriveTirContact

using P = Param;

// The equations cited: Pacejka, Tire and Vehicle Dynamics, 3rd ed. (2012),
// chapter 4 (4.E*) and appendix 3 (A3.*), as MF-Tyre/MF-Swift 6.1 use them.
class Derivation {
 public:
  Derivation(const TirFile& file, const Parameters& belt, const std::map<Param, double>& given,
             TirContact* out)
      : file_(file), given_(given), out_(out), p_(belt) {
    for (const auto& [q, v] : given) p_[q] = v;
  }

  void Run() {
    Version();
    const std::optional<double> fnomin = Get("VERTICAL", "FNOMIN");
    if (!fnomin) {
      if (!file_.HasSection("LONGITUDINAL_COEFFICIENTS") && !file_.HasSection("LATERAL_COEFFICIENTS")) {
        Note("no [VERTICAL] FNOMIN: no contact value is derived (the file has no Magic Formula "
             "block)");
        return;
      }
      for (Param q : {P::F_cz0, P::K_cx, P::sigma_cx, P::r_e0, P::K_cy, P::sigma_cy, P::r_l0, P::t_0}) {
        Skip(q, "[VERTICAL] FNOMIN, the Magic Formula's nominal load");
      }
      return;
    }
    fz0_ = Positive("VERTICAL", "FNOMIN");
    if (!given_.count(P::F_cz0)) Set(P::F_cz0, fz0_, "[VERTICAL] FNOMIN, the nominal load");
    load_ = p_[P::F_cz0];
    out_->load = load_;
    // Normalised load and pressure (4.E1, 4.E2a, 4.E2b).
    fz0_scaled_ = fz0_ * (file_.Find("SCALING_COEFFICIENTS", "LFZO")
                              ? Positive("SCALING_COEFFICIENTS", "LFZO") : 1);
    dfz_ = (load_ - fz0_scaled_) / fz0_scaled_;
    const bool pressures = file_.Find("OPERATING_CONDITIONS", "INFLPRES") &&
                           file_.Find("OPERATING_CONDITIONS", "NOMPRES");
    if (mf6_ && pressures) {
      const double p = Positive("OPERATING_CONDITIONS", "INFLPRES");
      const double p0 = Positive("OPERATING_CONDITIONS", "NOMPRES");
      dpi_ = (p - p0) / p0;
    }
    out_->summary = "contact values of MF " + out_->version + " at F_cz0 = " + ShortNumber(load_) +
                    " N, zero slip, camber and speed, " +
                    (!mf6_ ? std::string("without pressure terms (MF 5.x)")
                           : pressures ? "at the file's inflation pressure (dp_i = " + ShortNumber(dpi_) + ")"
                                       : std::string("at the nominal pressure (no INFLPRES and NOMPRES)"));
    Vertical();
    EffectiveRadius();
    SlipStiffnesses();
    Trail();
    RelaxationLengths();
    BeltLoadInfluence();
  }

 private:
  void Note(const std::string& line) { out_->notes.push_back(line); }

  void Version() {
    const std::optional<double> fittyp = Get("MODEL", "FITTYP");
    if (!fittyp) {
      Note("no [MODEL] FITTYP: read as MF 6.1");
      out_->version = "6.1";
    } else if (*fittyp == 61 || *fittyp == 62) {
      out_->version = *fittyp == 61 ? "6.1" : "6.2";
    } else {
      out_->version = "5.x";
      mf6_ = false;
    }
  }

  // The number KEY of [SECTION]; nullopt when absent; a quoted string fails.
  std::optional<double> Get(const char* section, const char* key) const {
    const TirEntry* e = file_.Find(section, key);
    if (!e) return std::nullopt;
    if (!e->number) throw Failure{e->Where(), "must be a number, not a quoted string"};
    return *e->number;
  }
  double Or(const char* section, const char* key, double fallback) const {
    return Get(section, key).value_or(fallback);
  }
  double Positive(const char* section, const char* key) const {
    const double v = *Get(section, key);
    if (!(v > 0)) {
      throw Failure{file_.Find(section, key)->Where(), "must be positive, not " + TirNumber(v)};
    }
    return v;
  }
  // The keys of `names` ("SECTION KEY") that the file lacks, as "[SECTION] KEY, ...".
  std::string Lacking(std::initializer_list<std::pair<const char*, const char*>> keys) const {
    std::string out;
    for (const auto& [section, key] : keys) {
      if (!file_.Find(section, key)) {
        out += (out.empty() ? "" : ", ") + std::string("[") + section + "] " + key;
      }
    }
    return out;
  }

  // Records `value` for `q` unless given by hand; a non-positive value is a note.
  void Set(Param q, double value, const std::string& from) {
    if (given_.count(q)) return;
    if (!(value > 0) || !std::isfinite(value)) {
      Note(std::string(ParamName(q)) + " not derived: " + from + " gives " + ShortNumber(value) +
           ", not a positive number");
      return;
    }
    p_[q] = value;
    out_->derived.push_back({q, value, from});
  }
  bool Skip(Param q, const std::string& lacking) {
    if (given_.count(q)) return true;
    if (lacking.empty()) return false;
    Note(std::string(ParamName(q)) + " not derived: the file has no " + lacking);
    return true;
  }

  // k_cz and r_l0 from the vertical law F_z = F_z0 (1 + p_Fz1 dp_i)(q_Fz1 x +
  // q_Fz2 x^2), x = rho_z/R_0 (A3.3): q_Fz1 from C_z at FNOMIN (MF 6.x, A3.4)
  // or at zero deflection (5.x), unless the file gives Q_FZ1.
  void Vertical() {
    const std::string lacking = Lacking({{"VERTICAL", "VERTICAL_STIFFNESS"}, {"DIMENSION", "UNLOADED_RADIUS"}});
    if (!lacking.empty()) {
      Skip(P::r_l0, lacking);
      if (!given_.count(P::k_cz)) {
        Note("k_cz is the belt block's (VERTICAL_STIFFNESS as the stiffness at F_cz0): the file "
             "has no " + lacking + " for the vertical law");
      }
      return;
    }
    const double cz0 = Positive("VERTICAL", "VERTICAL_STIFFNESS");
    const double r0 = Positive("DIMENSION", "UNLOADED_RADIUS");
    const double q2 = Or("VERTICAL", "Q_FZ2", 0);
    const double pressure = mf6_ ? 1 + Or("VERTICAL", "PFZ1", 0) * dpi_ : 1;
    if (!(pressure > 0)) {
      throw Failure{file_.Find("VERTICAL", "PFZ1")->Where(),
                    "with dp_i = " + ShortNumber(dpi_) + " it makes the vertical stiffness "
                    "factor 1 + PFZ1 dp_i = " + ShortNumber(pressure) + ", not positive"};
    }
    double q1_given = Or("VERTICAL", "Q_FZ1", 0);
    if (q1_given != 0 && mf6_) {
      Note("[VERTICAL] Q_FZ1 is not used: MF 6.x derives q_Fz1 from VERTICAL_STIFFNESS (A3.4)");
      q1_given = 0;
    }
    const TirEntry* culprit = file_.Find("VERTICAL", q1_given != 0 ? "Q_FZ1" : "Q_FZ2");
    if (!culprit) culprit = file_.Find("VERTICAL", "VERTICAL_STIFFNESS");
    double q1 = cz0 * r0 / fz0_;
    std::string law = mf6_ ? "q_Fz1 = sqrt((VERTICAL_STIFFNESS R_0/FNOMIN)^2 - 4 Q_FZ2) (A3.4: "
                             "VERTICAL_STIFFNESS is the tangent stiffness at FNOMIN in MF 6.x)"
                           : "q_Fz1 = VERTICAL_STIFFNESS R_0/FNOMIN (MF 5.x: the stiffness at "
                             "zero deflection)";
    if (q1_given != 0) {
      q1 = q1_given;
      law = "q_Fz1 = [VERTICAL] Q_FZ1";
    } else if (mf6_) {
      const double square = q1 * q1 - 4 * q2;
      if (!(square > 0)) {
        throw Failure{culprit->Where(),
                      "with Q_FZ2 = " + TirNumber(q2) + " the vertical law has no solution "
                      "((VERTICAL_STIFFNESS R_0/FNOMIN)^2 - 4 Q_FZ2 = " + ShortNumber(square) + ")"};
      }
      q1 = std::sqrt(square);
    }
    // The deflection at the load: q2 x^2 + q1 x = c, its positive root.
    const double c = load_ / (fz0_ * pressure);
    const double root = q1 * q1 + 4 * q2 * c;
    if (!(q1 > 0) || !(root > 0)) {
      throw Failure{culprit->Where(),
                    "the vertical law (q_Fz1 = " + TirNumber(q1) + ", Q_FZ2 = " + TirNumber(q2) +
                        ") gives no deflection at F_cz0 = " + TirNumber(load_) + " N"};
    }
    const double x = 2 * c / (q1 + std::sqrt(root));
    const double tangent = fz0_ * pressure / r0 * std::sqrt(root);  // dF_z/drho_z
    const std::string at = "at F_cz0 = " + ShortNumber(load_) + " N";
    if (!given_.count(P::k_cz)) {
      if (!(tangent < p_[P::k_bz])) {
        throw Failure{file_.Find("VERTICAL", "VERTICAL_STIFFNESS")->Where(),
                      "the vertical law's stiffness at F_cz0 = " + ShortNumber(load_) + " N, " +
                          ShortNumber(tangent) + " N/m, is not below k_bz = " +
                          ShortNumber(p_[P::k_bz]) + " N/m (FREQ_LONG): no contact stiffness k_cz "
                          "in series gives it"};
      }
      Set(P::k_cz, 1 / (1 / tangent - 1 / p_[P::k_bz]),
          "1/(1/C_z - 1/k_bz), C_z = " + ShortNumber(tangent) + " N/m the tangent of the vertical "
          "law " + at + " (A3.3), " + law);
    }
    const double r_omega = r0 * Or("VERTICAL", "Q_RE0", 1);  // at standstill (A3.1)
    Set(P::r_l0, r_omega - x * r0,
        "R_0 Q_RE0 - rho_z, rho_z the deflection of the vertical law " + at + " (A3.3)");
  }

  // r_e0 = R_omega - (F_z0/C_z)(F_reff F_z/F_z0 + D_reff atan(B_reff F_z/F_z0)) (A3.6).
  void EffectiveRadius() {
    if (Skip(P::r_e0, Lacking({{"DIMENSION", "UNLOADED_RADIUS"},
                               {"VERTICAL", "VERTICAL_STIFFNESS"}, {"VERTICAL", "BREFF"},
                               {"VERTICAL", "DREFF"}, {"VERTICAL", "FREFF"}}))) {
      return;
    }
    const double r_omega = Positive("DIMENSION", "UNLOADED_RADIUS") * Or("VERTICAL", "Q_RE0", 1);
    const double cz = Positive("VERTICAL", "VERTICAL_STIFFNESS") *
                      (mf6_ ? 1 + Or("VERTICAL", "PFZ1", 0) * dpi_ : 1);  // (A3.5)
    const double n = load_ / fz0_;
    Set(P::r_e0,
        r_omega - fz0_ / cz * (*Get("VERTICAL", "FREFF") * n +
                               *Get("VERTICAL", "DREFF") * std::atan(*Get("VERTICAL", "BREFF") * n)),
        "R_0 Q_RE0 - (FNOMIN/C_z)(FREFF F_z/FNOMIN + DREFF atan(BREFF F_z/FNOMIN)) at F_z = "
        "F_cz0 (A3.6)");
  }

  // K_cx = |K_xkappa| (4.E15), K_cy = |K_yalpha| at zero camber (4.E25).
  void SlipStiffnesses() {
    if (!Skip(P::K_cx, Lacking({{"LONGITUDINAL_COEFFICIENTS", "PKX1"}}))) {
      const char* s = "LONGITUDINAL_COEFFICIENTS";
      const double k = load_ * (*Get(s, "PKX1") + Or(s, "PKX2", 0) * dfz_) *
                       std::exp(Or(s, "PKX3", 0) * dfz_) *
                       (1 + Or(s, "PPX1", 0) * dpi_ + Or(s, "PPX2", 0) * dpi_ * dpi_) *
                       Or("SCALING_COEFFICIENTS", "LKX", 1);
      Set(P::K_cx, std::abs(k),
          "|F_z (PKX1 + PKX2 df_z) exp(PKX3 df_z)(1 + PPX1 dp_i + PPX2 dp_i^2) LKX| at F_z = "
          "F_cz0 (4.E15)");
    }
    if (!Skip(P::K_cy, Lacking({{"LATERAL_COEFFICIENTS", "PKY1"}, {"LATERAL_COEFFICIENTS", "PKY2"}}))) {
      const char* s = "LATERAL_COEFFICIENTS";
      const double curvature = mf6_ ? Or(s, "PKY4", 2) : 2;  // 5.x: sin(2 atan(.))
      if (*Get(s, "PKY2") == 0) throw Failure{file_.Find(s, "PKY2")->Where(), "must not be 0"};
      const double k = *Get(s, "PKY1") * fz0_scaled_ * (1 + Or(s, "PPY1", 0) * dpi_) *
                       std::sin(curvature * std::atan(load_ / (*Get(s, "PKY2") *
                                                               (1 + Or(s, "PPY2", 0) * dpi_) *
                                                               fz0_scaled_))) *
                       Or("SCALING_COEFFICIENTS", "LKY", 1);
      Set(P::K_cy, std::abs(k),
          std::string("|PKY1 F_z0' (1 + PPY1 dp_i) sin(") + (mf6_ ? "PKY4" : "2") +
              " atan(F_z/(PKY2 (1 + PPY2 dp_i) F_z0'))) LKY| at F_z = F_cz0, zero camber (4.E25)");
    }
  }

  // t_0 = D_t0 = F_z (R_0/F_z0')(QDZ1 + QDZ2 df_z)(1 - PPZ1 dp_i) LTR, the trail
  // at zero slip and camber (4.E42).
  void Trail() {
    if (Skip(P::t_0, Lacking({{"ALIGNING_COEFFICIENTS", "QDZ1"}, {"DIMENSION", "UNLOADED_RADIUS"}}))) {
      return;
    }
    const char* s = "ALIGNING_COEFFICIENTS";
    Set(P::t_0,
        load_ * Positive("DIMENSION", "UNLOADED_RADIUS") / fz0_scaled_ *
            (*Get(s, "QDZ1") + Or(s, "QDZ2", 0) * dfz_) * (1 - Or(s, "PPZ1", 0) * dpi_) *
            Or("SCALING_COEFFICIENTS", "LTR", 1),
        "F_z (R_0/F_z0')(QDZ1 + QDZ2 df_z)(1 - PPZ1 dp_i) LTR at F_z = F_cz0 (4.E42)");
  }

  // sigma = K (1/C - the belt's compliances): the series relation export
  // writes (docs/tir.md), with C the overall stiffness at the load (A3.10).
  void RelaxationLengths() {
    const char* s = "STRUCTURAL";
    const auto relax = [&](Param sigma, Param slip, const char* key, const char* k1,
                           const char* k2, const char* k3, double belt, const std::string& text) {
      if (Skip(sigma, Lacking({{s, key}}))) return;
      if (!p_.IsSet(slip)) {
        Note(std::string(ParamName(sigma)) + " not derived: it needs " + ParamName(slip));
        return;
      }
      const double c = *Get(s, key) * (1 + Or(s, k1, 0) * dfz_ + Or(s, k2, 0) * dfz_ * dfz_) *
                       (1 + Or(s, k3, 0) * dpi_);
      if (!(c > 0)) {
        Note(std::string(ParamName(sigma)) + " not derived: [" + s + "] " + key + " at F_cz0 (with " +
             k1 + ", " + k2 + ", " + k3 + ") comes out " + ShortNumber(c) + " N/m, not positive");
        return;
      }
      const double value = p_[slip] * (1 / c - belt);
      if (value > 0) {
        Set(sigma, value, text);
        return;
      }
      Note(std::string(ParamName(sigma)) + " not derived: [" + s + "] " + key + " = " +
           ShortNumber(c) + " N/m at F_cz0 is stiffer than the belt allows (the belt alone gives " +
           ShortNumber(1 / belt) + " N/m; the contact's share comes out " + ShortNumber(value) +
           " m): the file's carcass and belt do not agree");
    };
    if (p_.IsSet(P::r_e0)) {
      relax(P::sigma_cx, P::K_cx, "LONGITUDINAL_STIFFNESS", "PCFX1", "PCFX2", "PCFX3",
            1 / p_[P::k_bx] + p_[P::r_e0] * p_[P::r_e0] / p_[P::k_btheta],
            "K_cx (1/C_x - 1/k_bx - r_e0^2/k_btheta), C_x = LONGITUDINAL_STIFFNESS (1 + PCFX1 "
            "df_z + PCFX2 df_z^2)(1 + PCFX3 dp_i) (A3.10)");
    } else if (!given_.count(P::sigma_cx)) {
      Note("sigma_cx not derived: it needs r_e0");
    }
    if (p_.IsSet(P::r_l0)) {
      const double r = p_[P::r_l0];
      relax(P::sigma_cy, P::K_cy, "LATERAL_STIFFNESS", "PCFY1", "PCFY2", "PCFY3",
            1 / p_[P::k_by] + r * r / (p_[P::k_bgamma] + r * load_),
            "K_cy (1/C_y - 1/k_by - r_l0^2/(k_bgamma + r_l0 F_cz0)), C_y = LATERAL_STIFFNESS "
            "(1 + PCFY1 df_z + PCFY2 df_z^2)(1 + PCFY3 dp_i) (A3.10)");
    } else if (!given_.count(P::sigma_cy)) {
      Note("sigma_cy not derived: it needs r_l0");
    }
  }

  void BeltLoadInfluence() {
    for (const char* key : {"Q_BVX", "Q_BVT"}) {
      const std::optional<double> q = Get("STRUCTURAL", key);
      if (q && *q != 0) {
        Note(std::string("[STRUCTURAL] ") + key + " = " + TirNumber(*q) +
             ": MF-Swift changes the belt's in-plane stiffnesses with load and speed; ringid's "
             "k_b* are the file's, which hold at FNOMIN and standstill only");
      }
    }
  }

  const TirFile& file_;
  const std::map<Param, double>& given_;
  TirContact* out_;
  Parameters p_;  // the belt, the values given and those derived so far
  bool mf6_ = true;
  double fz0_ = 0, fz0_scaled_ = 0, load_ = 0, dfz_ = 0, dpi_ = 0;
};

}  // namespace

const std::vector<std::string>& TirSectionsRead() {
  static const std::vector<std::string> sections = {
      "UNITS", "MODEL", "DIMENSION", "OPERATING_CONDITIONS", "INERTIA", "VERTICAL",
      "STRUCTURAL", "SCALING_COEFFICIENTS", "LONGITUDINAL_COEFFICIENTS",
      "LATERAL_COEFFICIENTS", "ALIGNING_COEFFICIENTS"};
  return sections;
}

bool DeriveTirContact(const TirFile& file, const Parameters& belt,
                      const std::map<Param, double>& given, TirContact* contact,
                      LoadError* error) {
  *contact = TirContact{};
  error->file = file.path;
  error->field.clear();
  return Captured(error, [&] { Derivation(file, belt, given, contact).Run(); });
}

}  // namespace ringid
