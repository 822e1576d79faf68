// A rigid point probe pressing on one surface node with a penalty spring (Wriggers, Computational Contact
// Mechanics 2006, sec. 2.5.3: penalty method, energy k/2 <g>^2 of the penetration g), and the haptic local
// model that outputs the probe force between two FEM steps without waiting for the next one (the local linear
// update of Cavusoglu & Tendick 2000 / Nilsson & Dieckmann 2003): between synchronisation points the contact
// node moves as y = y* + v* (t - t*) - c (f - f*), where (y*, v*, f*) are the node's position, velocity and
// probe force at the last synchronisation and c the contact compliance of the node from the current
// factorisation of the effective tangent (e^T K_eff^{-1} e: one extra solve per direction); with the penalty
// law f = k <y - y_d>_+ this gives the closed form f = k <y* + v* (t - t*) + c f* - y_d>_+ / (1 + k c).
// (Adding a* (t - t*)^2 / 2 is more accurate for small steps but amplifies unresolved contact oscillations.)
// The local model is consistent: its error at the synchronisation points vanishes as the FEM step shrinks.
#pragma once

#include "fem/second_order_system.hpp"

namespace suite::fem {

// The elastic system plus the probe's penalty force on free DOF `dof` (the probe acts along -y): penetration
// g = X + u[dof] - y_probe, force k <g>_+ added to the internal force, k on the tangent diagonal in contact.
class ProbeSystem final : public SecondOrderSystem {
public:
  // active = false: the penalty is not added (distributed assembly: only one rank adds it to the partial sums).
  ProbeSystem(SecondOrderSystem* body, int dof, double X, double k, bool active = true);
  const SymCsc& pattern() const override { return body_->pattern(); }
  bool internalForce(const double* u, double* f, std::vector<double>* K, double* energy) override;
  void setProbe(double y) { y_probe_ = y; }
  double probe() const { return y_probe_; }
  // Probe force (reaction on the user, >= 0) for displacement u.
  double force(const double* u) const;
  double position(const double* u) const { return X_ + u[dof_]; }
  int dof() const { return dof_; }
  double stiffness() const { return k_; }

private:
  SecondOrderSystem* body_;
  int dof_, diag_ = -1;
  double X_, k_, y_probe_ = 1e300;
  bool active_ = true;
};

// The haptic local model between synchronisations.
struct HapticLocalModel {
  // sync time, node position and velocity, force, compliance, penalty stiffness
  double t = 0, y = 0, v = 0, f = 0, c = 0, k = 0;
  double force(double time, double y_probe) const {
    const double g = y + v * (time - t) + c * f - y_probe;
    return g > 0 ? k * g / (1 + k * c) : 0.0;
  }
};

} // namespace suite::fem
