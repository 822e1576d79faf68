// rf-char face fluxes of one grid line for the `weno5` scheme (rf_char.hpp; Weno5Line::faceFluxes with rf and
// characteristic), organised for speed: structure-of-arrays over the cells and faces of the line, loops over
// the faces that the compiler vectorises, and one WENO-Z reconstruction (of l_c f on the upwind side) for
// each upwinded field, two (the split l_c (f +- alpha_c U) / 2) only for the fields whose sign changes. See
// weno5_line_rf.cpp. References: as weno5_line.hpp and rf_char.hpp.
#pragma once

#include "euler/gas_nd.hpp"

#include <vector>

namespace suite::euler {

template <int NV> class Weno5RfLine {
public:
  using V = typename LineGas<NV>::V;

  // q: nface + 5 cells of a line; h[k]: the flux at the face between cells k + 2 and k + 3. alpha: the
  // Lax-Friedrichs speed of the split fields when !local_lf (otherwise alpha_c = max |lambda_c| over the
  // stencil).
  void faceFluxes(const V* q, int nface, double alpha, bool local_lf, double g, V* h);

private:
  void prepareCells(const V* q, int ncell, double g);
  void faceEigen(int nface, double g);
  template <int GRP> void groupAlpha(int nface, double alpha, bool local_lf);
  template <int C> void projectField(int nface);
  void wenoValues(int njob);
  void combine(int nface, V* h);

  int ncell_ = 0, nsplit_ = 0, ndense_ = 0;
  int block_[NV] = {};        // per field: its block of f- jobs (dense split), or -1
  int gsplit_[3] = {0, 0, 0}; // per sign group (fields u - c, u, u + c): the faces where it changes sign
  // Per cell (index m) cs_ = [flux f_j (NV), u, c, sqrt(rho), sqrt(rho) u_n.., sqrt(rho) H, U (NV)], cs_[i
  // ncell + m]; per face (index k) fs_ = [L (NV x NV; its structural zeros unset), u, c, H, v2, u_t.., sign
  // of the fields u - c, u, u + c], fs_[i nface + k]; the WENO jobs: per field c the upwind (or f+) stencil
  // of face k is job c nface + k, then the blocks of f- stencils of the fields with many split faces
  // (block_), then one job per split (field, face) of the other fields (target_: the job it adds to); st_[i
  // jcap + n]: element i of job n, w_[n] its WENO-Z value. ac_[grp nface + k]: the Lax-Friedrichs speed of
  // the split faces of sign group grp.
  std::vector<double> cs_, fs_, st_, w_, ac_, spare_;
  std::vector<int> target_;
};

extern template class Weno5RfLine<3>;
extern template class Weno5RfLine<4>;
extern template class Weno5RfLine<5>;

} // namespace suite::euler
