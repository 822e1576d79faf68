// The semi-discrete equations of motion M a + C v + f(u) = f_ext on free DOFs, as seen by the time
// integrators and the static solver: a fixed sparse pattern shared by M, C and the tangent K = df/du.
#pragma once

#include "fem/sparse.hpp"

#include <vector>

namespace suite::fem {

// The semi-discrete system on free DOFs: a fixed sparse pattern shared by M, C, K.
class SecondOrderSystem {
public:
  virtual ~SecondOrderSystem() = default;
  virtual const SymCsc& pattern() const = 0;
  // Internal force f(u) and (if K) tangent values; returns false if u is inadmissible (an element inverted).
  virtual bool internalForce(const double* u, double* f, std::vector<double>* K, double* energy) = 0;
  virtual bool isLinear() const { return false; }
};

// Constant stiffness K (f = K u), for tests and linear models.
class LinearSecondOrderSystem final : public SecondOrderSystem {
public:
  explicit LinearSecondOrderSystem(SymCsc K) : K_(std::move(K)) {}
  const SymCsc& pattern() const override { return K_; }
  bool internalForce(const double* u, double* f, std::vector<double>* K, double* energy) override;
  bool isLinear() const override { return true; }

private:
  SymCsc K_;
};

} // namespace suite::fem
