// Unmodelled effects of docs/conventions.md §4: each one small unit that extends
// the baseline system and leaves it unchanged with its parameters at zero.
#ifndef RINGID_MODEL_EFFECTS_H_
#define RINGID_MODEL_EFFECTS_H_

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/enum_names.h"
#include "model/parameters.h"
#include "model/system.h"

namespace ringid {

class Effect {
 public:
  virtual ~Effect() = default;
  virtual const char* name() const = 0;
  // The parameters the effect adds (baseline value 0 unless noted).
  virtual std::vector<Param> parameters() const = 0;
  // The parameter that sizes the effect: at 0 the model is the baseline.
  virtual Param size() const = 0;
  virtual void Apply(const Parameters& p, MechanicalSystem* s) const = 0;
  virtual void Apply(const ParameterArray<ParameterJet>& p,
                     BasicSystem<ParameterJet>* s) const = 0;
};

// An effect written once, as Derived::ApplyTo(p, s) for either scalar.
template <class Derived>
class EffectOf : public Effect {
 public:
  void Apply(const Parameters& p, MechanicalSystem* s) const final {
    static_cast<const Derived*>(this)->ApplyTo(p, s);
  }
  void Apply(const ParameterArray<ParameterJet>& p, BasicSystem<ParameterJet>* s) const final {
    static_cast<const Derived*>(this)->ApplyTo(p, s);
  }
};

// The catalogue, in the order of docs/conventions.md §4; pointers live for
// the program's life.
const std::vector<const Effect*>& EffectCatalogue();
const Effect* FindEffect(const std::string& name);

// In reports an effect is named by name(), and no effect (nullptr) "none".
inline constexpr char kNoEffect[] = "none";
inline const char* EffectName(const Effect* effect) { return effect ? effect->name() : kNoEffect; }
std::vector<std::string> EffectNames(const std::vector<const Effect*>& effects);

template <>
struct PointerNames<Effect> {
  static const char* ToString(const Effect* effect) { return EffectName(effect); }
  static std::optional<const Effect*> FromString(std::string_view name);
  static std::string Choices();
};

}  // namespace ringid

#endif  // RINGID_MODEL_EFFECTS_H_
