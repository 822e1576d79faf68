// Penalty point probe on one surface node; see probe_contact.hpp.
#include "fem/probe_contact.hpp"

namespace suite::fem {

ProbeSystem::ProbeSystem(SecondOrderSystem* body, int dof, double X, double k, bool active)
    : body_(body), dof_(dof), X_(X), k_(k), active_(active) {
  const SymCsc& P = body->pattern();
  // Upper triangle with sorted rows: the diagonal is the last entry of its column.
  if (dof >= 0 && dof < P.n && P.colptr[dof + 1] > P.colptr[dof] && P.rowind[P.colptr[dof + 1] - 1] == dof)
    diag_ = P.colptr[dof + 1] - 1;
}

double ProbeSystem::force(const double* u) const {
  const double g = X_ + u[dof_] - y_probe_;
  return g > 0 ? k_ * g : 0.0;
}

bool ProbeSystem::internalForce(const double* u, double* f, std::vector<double>* K, double* energy) {
  const bool ok = body_->internalForce(u, f, K, energy);
  const double g = X_ + u[dof_] - y_probe_;
  if (g > 0 && active_) {
    f[dof_] += k_ * g;
    if (K && diag_ >= 0) (*K)[diag_] += k_;
    if (energy) *energy += 0.5 * k_ * g * g;
  }
  return ok;
}

} // namespace suite::fem
