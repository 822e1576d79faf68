// Face fluxes of one grid line for the `weno5` scheme (explicit fifth-order WENO-Z rows everywhere, weno5.hpp).
// rf-char upwinding (rf_char.hpp, the default; characteristic-wise) goes to Weno5RfLine (weno5_line_rf.hpp).
// Here Lax-Friedrichs flux splitting, characteristic-wise (Roe eigenvectors of each face, gas_nd.hpp) or
// component-wise, with the arithmetic of DirectionSweep's row-by-row path (bitwise the same fluxes), organised
// for speed: per cell once the flux, |u| + c and the per-state part of the Roe average; per face once the
// eigenvectors and the projection of the stencil's split fluxes (products with the structural zeros of L and R
// skipped: exact, as a sum that starts at +0 never becomes -0); then the WENO-Z values of every face, field and
// split sign of the line in one loop over the faces, which the compiler vectorises.
// References: Shu, ICASE report 97-65 (1997), sec. 2.3 (flux splitting, characteristic decomposition);
// Jiang & Shu, J. Comput. Phys. 126 (1996) 202 and Borges et al., J. Comput. Phys. 227 (2008) 3191 (WENO-Z).
#pragma once

#include "euler/gas_nd.hpp"
#include "euler/weno5_line_rf.hpp"

#include <array>
#include <vector>

namespace suite::euler {

template <int NV> class Weno5Line {
public:
  using G = LineGas<NV>;
  using V = typename G::V;

  // q: nface + 5 cells of a line (3 ghosts each side of its nface - 1 cells); h[k]: the flux at the face between
  // cells k + 2 and k + 3. alpha: the Lax-Friedrichs speed when !local_lf (otherwise max |u| + c over each
  // face's six-cell stencil). rf: rf-char upwinding (rf_char.hpp; with characteristic only). flux_scale: the
  // grid's largest momentum flux; characteristic-wise, a face whose basis is ill-conditioned against it
  // (characteristic_conditioning.hpp) is split component-wise instead (Lax-Friedrichs). Returns the number of
  // such faces.
  int faceFluxes(const V* q, int nface, double alpha, bool local_lf, bool characteristic, bool rf, double g,
                 double flux_scale, V* h);

private:
  void prepareCells(const V* q, int ncell, bool local_lf, bool characteristic, double g);
  double faceAlpha(int k, double alpha, bool local_lf) const;
  void projectFace(int k, int nface, bool characteristic);
  void wenoValues(int nface);
  void combineFace(int k, int nface, bool characteristic, V* h) const;
  int componentwiseFaces(const V* q, int nface, double alpha, bool local_lf, double g, double flux_scale,
                         V* h);

  int ncell_ = 0;
  std::vector<double> qt_, ft_, speed_; // cell-major per component: qt_[j * ncell + m]
  std::vector<double> p_;               // per cell: its pressure (componentwiseFaces)
  std::vector<typename G::RoeState> roe_;
  std::vector<double> alpha_;            // per face: the Lax-Friedrichs speed
  std::vector<typename G::Eigen> eigen_; // per face: the Roe eigenvectors
  std::vector<double> st_; // stencils: st_[((2 c + s) 5 + i) nface + k], element i of field c, sign s, face k
  std::vector<double> w_;  // WENO-Z values: w_[(2 c + s) nface + k]
  Weno5RfLine<NV> rf_;     // rf-char lines
};

extern template class Weno5Line<3>;
extern template class Weno5Line<4>;
extern template class Weno5Line<5>;

} // namespace suite::euler
