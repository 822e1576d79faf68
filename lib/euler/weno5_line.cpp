// Face fluxes of one grid line for the `weno5` scheme (see weno5_line.hpp).
#include "euler/weno5_line.hpp"

#include "euler/characteristic_conditioning.hpp"
#include "euler/weno5.hpp"

#include <algorithm>
#include <cmath>

namespace suite::euler {

template <int NV>
int Weno5Line<NV>::faceFluxes(const V* q, int nface, double alpha, bool local_lf, bool characteristic,
                              bool rf, double g, double flux_scale, V* h) {
  if (rf && characteristic) {
    rf_.faceFluxes(q, nface, alpha, local_lf, g, h);
    return componentwiseFaces(q, nface, alpha, local_lf, g, flux_scale, h);
  }
  prepareCells(q, nface + 5, local_lf, characteristic, g);
  alpha_.resize(nface);
  for (int k = 0; k < nface; ++k) alpha_[k] = faceAlpha(k, alpha, local_lf);
  if (characteristic) { // a loop of its own: the square roots and divisions of neighbouring faces overlap
    if ((int)eigen_.size() < nface) eigen_.resize(nface, typename G::Eigen{}); // zeros, kept by roeInto
    for (int k = 0; k < nface; ++k) G::roeInto(roe_[k + 2], roe_[k + 3], g, &eigen_[k]);
  }
  st_.resize((size_t)2 * NV * 5 * nface);
  for (int k = 0; k < nface; ++k) projectFace(k, nface, characteristic);
  wenoValues(nface);
  for (int k = 0; k < nface; ++k) combineFace(k, nface, characteristic, h);
  return characteristic ? componentwiseFaces(q, nface, alpha, local_lf, g, flux_scale, h) : 0;
}

template <int NV>
void Weno5Line<NV>::prepareCells(const V* q, int ncell, bool local_lf, bool characteristic, double g) {
  ncell_ = ncell;
  qt_.resize((size_t)NV * ncell);
  ft_.resize((size_t)NV * ncell);
  speed_.resize(ncell);
  roe_.resize(ncell);
  for (int m = 0; m < ncell; ++m) {
    const V f = G::flux(q[m], g);
    for (int j = 0; j < NV; ++j) qt_[(size_t)j * ncell + m] = q[m][j], ft_[(size_t)j * ncell + m] = f[j];
    if (local_lf) speed_[m] = G::maxSpeed(q[m], g);
    if (characteristic) roe_[m] = G::roeState(q[m], g);
  }
}

// The Lax-Friedrichs speed of face k (as DirectionSweep::prepareLine).
template <int NV> double Weno5Line<NV>::faceAlpha(int k, double alpha, bool local_lf) const {
  if (!local_lf) return alpha;
  double a = 0.0;
  for (int m = 0; m < 6; ++m) a = std::max(a, speed_[k + m]);
  return a * (1.0 + 1e-12);
}

// The split fluxes f+ = (f + a U) / 2 of cells k .. k + 4 (lanes 0..4) and f- = (f - a U) / 2 of cells
// k + 1 .. k + 5 (lanes 5..9), times the left eigenvectors of face k, into the stencils st_: f+ left-biased
// (element i = cell k + i), f- mirrored (element i = cell k + 5 - i, lane 9 - i).
template <int NV> void Weno5Line<NV>::projectFace(int k, int nface, bool characteristic) {
  const double a = alpha_[k];
  double x[NV][10];
  for (int j = 0; j < NV; ++j) {
    const double* f = &ft_[(size_t)j * ncell_ + k];
    const double* u = &qt_[(size_t)j * ncell_ + k];
    for (int l = 0; l < 5; ++l) x[j][l] = 0.5 * (f[l] + a * u[l]);
    for (int l = 0; l < 5; ++l) x[j][5 + l] = 0.5 * (f[l + 1] - a * u[l + 1]);
  }
  const double* L = characteristic ? eigen_[k].L.data() : nullptr;
  for (int c = 0; c < NV; ++c) {
    double y[10];
    if (characteristic) {
      for (int l = 0; l < 10; ++l) y[l] = 0.0;
      for (int j = 0; j < NV; ++j)
        if (!G::leftZero(c, j)) {
          const double lcj = L[NV * c + j];
          for (int l = 0; l < 10; ++l) y[l] += lcj * x[j][l];
        }
    } else {
      for (int l = 0; l < 10; ++l) y[l] = x[c][l];
    }
    double* sp = &st_[(size_t)(2 * c) * 5 * nface + k];
    double* sm = &st_[(size_t)(2 * c + 1) * 5 * nface + k];
    for (int i = 0; i < 5; ++i) sp[(size_t)i * nface] = y[i], sm[(size_t)i * nface] = y[9 - i];
  }
}

template <int NV> void Weno5Line<NV>::wenoValues(int nface) {
  w_.resize((size_t)2 * NV * nface);
  for (int cs = 0; cs < 2 * NV; ++cs) {
    const double* v = &st_[(size_t)cs * 5 * nface];
    double* w = &w_[(size_t)cs * nface];
    for (int k = 0; k < nface; ++k)
      w[k] = weno5ZValue(v[k], v[nface + k], v[2 * nface + k], v[3 * nface + k], v[4 * nface + k]);
  }
}

// h[k] = R (h+ + h-) (component-wise: h+ + h-), as the row path's R times the rows' r / b with b = 1.
template <int NV> void Weno5Line<NV>::combineFace(int k, int nface, bool characteristic, V* h) const {
  double hc[NV];
  for (int c = 0; c < NV; ++c) hc[c] = w_[(size_t)(2 * c) * nface + k] + w_[(size_t)(2 * c + 1) * nface + k];
  if (!characteristic) {
    for (int i = 0; i < NV; ++i) h[k][i] = hc[i];
    return;
  }
  const typename G::M& R = eigen_[k].R;
  for (int i = 0; i < NV; ++i) {
    double s = 0.0;
    for (int j = 0; j < NV; ++j)
      if (!G::rightZero(i, j)) s += R[NV * i + j] * hc[j];
    h[k][i] = s;
  }
}

// The faces whose characteristic basis is ill-conditioned (characteristic_conditioning.hpp: the smaller of the
// face's cells' pressures against flux_scale) recomputed component-wise: h = w(f+) + w~(f-), f+- = (f +- a U) / 2
// with the face's Lax-Friedrichs speed a (faceAlpha) and the WENO5-Z values of the left- and right-biased
// stencils. Returns their number; one pass over the cells' pressures settles the common case, none.
template <int NV>
int Weno5Line<NV>::componentwiseFaces(const V* q, int nface, double alpha, bool local_lf, double g,
                                      double flux_scale, V* h) {
  const int ncell = nface + 5;
  p_.resize(ncell);
  double p_min = INFINITY;
  for (int m = 0; m < ncell; ++m) p_[m] = G::pressure(q[m], g), p_min = std::min(p_min, p_[m]);
  if (!characteristicIllConditioned(flux_scale, p_min)) return 0;
  if (local_lf) { // faceAlpha's speeds (the rf-char path has not set them)
    speed_.resize(ncell);
    for (int m = 0; m < ncell; ++m) speed_[m] = G::maxSpeed(q[m], g);
  }
  int count = 0;
  for (int k = 0; k < nface; ++k) {
    if (!characteristicIllConditioned(flux_scale, std::min(p_[k + 2], p_[k + 3]))) continue;
    ++count;
    const double a = faceAlpha(k, alpha, local_lf);
    V f[6];
    for (int m = 0; m < 6; ++m) f[m] = G::flux(q[k + m], g);
    for (int i = 0; i < NV; ++i) {
      double fp[6], fm[6];
      for (int m = 0; m < 6; ++m)
        fp[m] = 0.5 * (f[m][i] + a * q[k + m][i]), fm[m] = 0.5 * (f[m][i] - a * q[k + m][i]);
      h[k][i] =
          weno5ZValue(fp[0], fp[1], fp[2], fp[3], fp[4]) + weno5ZValue(fm[5], fm[4], fm[3], fm[2], fm[1]);
    }
  }
  return count;
}

template class Weno5Line<3>;
template class Weno5Line<4>;
template class Weno5Line<5>;

} // namespace suite::euler
