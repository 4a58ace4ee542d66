// The standing rigid-ring model of docs/model.md, optionally extended by effects.
#ifndef RINGID_MODEL_RIGID_RING_MODEL_H_
#define RINGID_MODEL_RIGID_RING_MODEL_H_

#include <functional>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "model/effects.h"
#include "model/modal.h"
#include "model/parameters.h"
#include "model/system.h"

namespace ringid {

// The one interface estimation sees: parameters in, labelled modes out.
// Clone and the Solve functions may be called from several threads at once
// (a campaign's jobs share one model); RigidRingModel's kept solutions lock.
class ModalModel {
 public:
  virtual ~ModalModel() = default;
  virtual std::unique_ptr<ModalModel> Clone() const = 0;
  // The modes at standstill, and rolling freely at a forward speed (m/s).
  ModalSolution Solve(const Parameters& p) const { return Solve(p, 0.0); }
  ModalSolution Solve(const Parameters& p, double speed_m_s) const {
    return Solve(p, speed_m_s, false);
  }
  // With `derivatives` each mode carries its derivatives with respect to
  // the parameters (ModeDerivatives), unless derivatives_undefined says why not.
  virtual ModalSolution Solve(const Parameters& p, double speed_m_s, bool derivatives) const = 0;
  // The modes at p labelled as those of `near`, the solution at a nearby
  // point and the same speed, where one strict step carries them (SolveNear);
  // else Solve(p, speed_m_s). A numeric derivative takes its perturbed points
  // so, to differentiate the branches of the point it perturbs.
  virtual ModalSolution SolveFrom(const ModalSolution& near, const Parameters& p,
                                  double speed_m_s) const {
    (void)near;
    return Solve(p, speed_m_s);
  }
  // The system at `speed_m_s` (model/system.h); with ParameterJet values,
  // every one carrying its derivatives with respect to the parameters.
  virtual MechanicalSystem Assemble(const Parameters& p, double speed_m_s) const = 0;
  virtual BasicSystem<ParameterJet> Assemble(const ParameterArray<ParameterJet>& p,
                                             double speed_m_s) const = 0;
  // The parameters Solve reads, in catalogue order.
  virtual std::vector<Param> parameters() const = 0;
};

class RigidRingModel final : public ModalModel {
 public:
  explicit RigidRingModel(std::vector<const Effect*> effects = {});

  // Eqs. (12) and (15) as corrected in docs/model.md, then each effect, then
  // the terms of rolling at speed_m_s (docs/rolling.md).
  MechanicalSystem Assemble(const Parameters& p, double speed_m_s = 0) const override;
  BasicSystem<ParameterJet> Assemble(const ParameterArray<ParameterJet>& p,
                                     double speed_m_s) const override;
  std::unique_ptr<ModalModel> Clone() const override {
    return std::make_unique<RigidRingModel>(*this);
  }
  using ModalModel::Solve;
  // At speed the labels follow the standing ones by continuation, taken at
  // p's anchor (each parameter rounded to kAnchorBits bits of mantissa) and
  // carried to p by one SolveNear step; at p itself where the standstill
  // labels differ, the anchor's were forced or that step fails
  // (docs/rolling.md §5). Labels are thus a function of p alone.
  ModalSolution Solve(const Parameters& p, double speed_m_s, bool derivatives) const override;
  ModalSolution SolveFrom(const ModalSolution& near, const Parameters& p,
                          double speed_m_s) const override;
  std::vector<Param> parameters() const override;
  const std::vector<const Effect*>& effects() const { return effects_; }
  bool Has(const Effect* effect) const;
  // This model with `effect` added.
  RigidRingModel With(const Effect* effect) const;

 private:
  static constexpr int kAnchorBits = 10;

  // The modes of the last kCapacity (parameters, speed) points solved. Each
  // condition of a fit solves the same points (numeric differentiation
  // perturbs the shared coordinates alike), a rolling one starts its
  // continuation from standstill, and nearby points share an anchor. A copy
  // starts empty; safe across threads.
  class SolutionCache {
   public:
    SolutionCache() = default;
    SolutionCache(const SolutionCache&) {}
    SolutionCache& operator=(const SolutionCache&) { return *this; }
    ModalSolution Get(const Parameters& p, double speed,
                      const std::function<ModalSolution()>& solve) const;

   private:
    struct Key {
      Parameters p;
      double speed;
    };
    static constexpr int kCapacity = 64;
    mutable std::mutex mutex_;
    mutable std::vector<std::pair<Key, std::shared_ptr<const ModalSolution>>> entries_;
    mutable int next_ = 0;
  };

  // The modes at standstill, labelled by energy; kept.
  ModalSolution Standing(const Parameters& p) const;
  // Continuation from standstill at p itself (SolveRolling).
  ModalSolution SolveByContinuation(const Parameters& p, double speed, bool derivatives,
                                    bool* forced = nullptr) const;

  std::vector<const Effect*> effects_;
  std::vector<Param> used_;
  SolutionCache standing_;  // speed 0
  SolutionCache anchors_;   // rolling, at anchors
};

}  // namespace ringid

#endif  // RINGID_MODEL_RIGID_RING_MODEL_H_
