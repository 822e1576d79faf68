// Interface fluxes on a distributed line (see line_operator.hpp for the method and references).
#include "euler/line_operator.hpp"

#include "euler/characteristic.hpp"
#include "euler/enopade6.hpp"
#include "euler/muscl2.hpp"
#include "euler/positivity.hpp"

#include <algorithm>
#include <cmath>

namespace suite::euler {

void LineOperator::divergence(const Vec3* h, int xm, double dx, Vec3* out) {
  const double inv = 1.0 / dx;
  for (int k = 0; k < xm; ++k)
    for (int c = 0; c < 3; ++c) out[k][c] = -(h[k + 1][c] - h[k][c]) * inv;
}

void LineOperator::interfaceFluxes(MPI_Comm comm, const Vec3* q, long long nx, long long xs, int xm,
                                   bool periodic, double alpha_global, double lambda, Vec3* h) {
  ++stats_.evaluations;
  const double g = opt_.gamma;
  const int ncell = xm + 2 * kGhost, nface = xm + 1;
  f_.resize(ncell);
  speed_.resize(ncell);
  rho_.resize(ncell);
  p_.resize(ncell);
  for (int m = 0; m < ncell; ++m) {
    f_[m] = physicalFlux(q[m], g);
    speed_[m] = maxWaveSpeed(q[m], g);
    rho_[m] = q[m][0];
    p_[m] = pressure(q[m], g);
  }
  alpha_.resize(nface);
  for (int k = 0; k < nface; ++k) {
    double a = alpha_global;
    if (opt_.local_lf && !scheme_->compact) { // compact rows need one alpha along the line (see header)
      a = 0.0;
      for (int m = 0; m < 6; ++m) a = std::max(a, speed_[k + m]);
      a *= 1.0 + 1e-12; // stay strictly above the wave speeds at the stencil cells
    }
    alpha_[k] = a;
  }

  if (scheme_->state_riemann) {
    for (int k = 0; k < nface; ++k) h[k] = muscl2Flux(q + k + 1, g);
  } else {
    const bool compact = scheme_->compact;
    pade_.assign(nface, 0);
    if (compact)
      for (int s = 0; s < 2; ++s) {
        A_[s].assign(9 * nface, 0.0);
        B_[s].assign(9 * nface, 0.0);
        C_[s].assign(9 * nface, 0.0);
        d_[s].assign(3 * nface, 0.0);
      }
    rhs_.assign(3 * nface, 0.0);
    for (int k = 0; k < nface; ++k) {
      const long long iface = xs + k;
      const bool boundary = !periodic && (iface == 0 || iface == nx);
      const Vec3* qs = q + k; // cells i-3 .. i+2 = j-2 .. j+3
      const Vec3* fs = f_.data() + k;
      const double a = alpha_[k];
      bool shock = !scheme_->hybrid;
      if (scheme_->hybrid) {
        shock = enoPadeShockRow(rho_.data() + k, p_.data() + k, opt_.shock_threshold);
        if (shock) ++stats_.shock_rows;
      }
      RowFunction fn = boundary ? (shock ? scheme_->boundary_shock : scheme_->boundary_smooth)
                                : (shock ? scheme_->shock_row : scheme_->smooth_row);
      if (compact && !shock && !boundary) { // Pade row: central, so the split cancels; conserved-space rhs
        pade_[k] = 1;
        for (int s = 0; s < 2; ++s) {
          for (int c = 0; c < 3; ++c) {
            A_[s][9 * k + 4 * c] = 1.0 / 3.0;
            B_[s][9 * k + 4 * c] = 1.0;
            C_[s][9 * k + 4 * c] = 1.0 / 3.0;
            double v[6];
            for (int m = 0; m < 6; ++m) v[m] = 0.5 * (fs[m][c] + (s == 0 ? a : -a) * qs[m][c]);
            d_[s][3 * k + c] = fn(v).r;
          }
        }
        continue;
      }
      // Split fluxes, projected on the characteristic fields of the Roe average at x_{j+1/2}.
      Eigensystem e;
      if (opt_.characteristic) e = roeEigensystem(qs[2], qs[3], g);
      double wp[3][6], wm[3][6];
      for (int m = 0; m < 6; ++m) {
        Vec3 fp, fm;
        for (int c = 0; c < 3; ++c) {
          fp[c] = 0.5 * (fs[m][c] + a * qs[m][c]);
          fm[c] = 0.5 * (fs[m][c] - a * qs[m][c]);
        }
        if (opt_.characteristic) {
          fp = mul(e.L, fp);
          fm = mul(e.L, fm);
        }
        for (int c = 0; c < 3; ++c) {
          wp[c][m] = fp[c];
          wm[c][m] = fm[c];
        }
      }
      Row rows[2][3];
      for (int c = 0; c < 3; ++c) {
        rows[0][c] = fn(wp[c]);
        rows[1][c] = mirrorRow(fn, wm[c]);
      }
      if (!compact) {
        Vec3 hc;
        for (int c = 0; c < 3; ++c) hc[c] = rows[0][c].r / rows[0][c].b + rows[1][c].r / rows[1][c].b;
        h[k] = opt_.characteristic ? mul(e.R, hc) : hc;
        continue;
      }
      bool explicit_row = true;
      for (int s = 0; s < 2; ++s)
        for (int c = 0; c < 3; ++c)
          explicit_row = explicit_row && rows[s][c].a == 0.0 && rows[s][c].c == 0.0 && rows[s][c].b == 1.0;
      for (int s = 0; s < 2; ++s) {
        for (int r = 0; r < 3; ++r) {
          if (explicit_row) { // a = c = 0, b = 1 exactly: the block row is the identity
            B_[s][9 * k + 4 * r] = 1.0;
            double sr = 0;
            if (opt_.characteristic)
              for (int c = 0; c < 3; ++c) sr += e.R[3 * r + c] * rows[s][c].r;
            else
              sr = rows[s][r].r;
            d_[s][3 * k + r] = sr;
            continue;
          }
          for (int cc = 0; cc < 3; ++cc) {
            double sa = 0, sb = 0, sc = 0;
            if (opt_.characteristic) {
              for (int c = 0; c < 3; ++c) {
                const double rl = e.R[3 * r + c] * e.L[3 * c + cc];
                sa += rl * rows[s][c].a;
                sb += rl * rows[s][c].b;
                sc += rl * rows[s][c].c;
              }
            } else if (r == cc) {
              sa = rows[s][r].a;
              sb = rows[s][r].b;
              sc = rows[s][r].c;
            }
            A_[s][9 * k + 3 * r + cc] = sa;
            B_[s][9 * k + 3 * r + cc] = sb;
            C_[s][9 * k + 3 * r + cc] = sc;
          }
          double sr = 0;
          if (opt_.characteristic)
            for (int c = 0; c < 3; ++c) sr += e.R[3 * r + c] * rows[s][c].r;
          else
            sr = rows[s][r].r;
          d_[s][3 * k + r] = sr;
        }
      }
    }
    if (compact) {
      // Rows owned by this rank: its cells' left faces, plus the last face of a non-periodic line.
      const int nown = xm + ((!periodic && xs + xm == nx) ? 1 : 0);
      int size = 1;
      MPI_Comm_size(comm, &size);
      // Boundary rows that are explicit (b = 1, a = c = 0) with identical components still fit the scalar
      // path.
      bool scalar = true;
      for (int k = 0; k < nown && scalar; ++k)
        if (!pade_[k]) {
          for (int s = 0; s < 2 && scalar; ++s)
            for (int e = 0; e < 9; ++e) {
              const double id = (e % 4 == 0) ? 1.0 : 0.0;
              if (A_[s][9 * k + e] != 0.0 || C_[s][9 * k + e] != 0.0 || B_[s][9 * k + e] != id)
                scalar = false;
            }
        }
      int all_scalar = scalar ? 1 : 0, global_scalar = all_scalar;
      if (size > 1) MPI_Allreduce(&all_scalar, &global_scalar, 1, MPI_INT, MPI_LAND, comm);
      x_.resize(3 * nface);
      if (global_scalar) {
        abc_.resize(3 * nown);
        for (int k = 0; k < nown; ++k) {
          abc_[3 * k] = A_[0][9 * k];
          abc_[3 * k + 1] = B_[0][9 * k];
          abc_[3 * k + 2] = C_[0][9 * k];
          for (int c = 0; c < 3; ++c) rhs_[3 * k + c] = d_[0][3 * k + c] + d_[1][3 * k + c];
        }
        if (opt_.gather_lines)
          gather_.solveScalar(comm, nown, abc_.data(), 3, rhs_.data(), periodic, xs, nface, x_.data());
        else
          sub_.solveScalar(comm, nown, abc_.data(), 3, rhs_.data(), periodic, xs, nface, x_.data());
        for (int k = 0; k < nface; ++k) h[k] = {x_[3 * k], x_[3 * k + 1], x_[3 * k + 2]};
      } else {
        for (int k = 0; k < nface; ++k) h[k] = {0.0, 0.0, 0.0};
        for (int s = 0; s < 2; ++s) {
          if (opt_.gather_lines)
            gather_.solve(comm, 3, nown, A_[s].data(), B_[s].data(), C_[s].data(), d_[s].data(), periodic, xs,
                          nface, x_.data());
          else
            sub_.solve(comm, 3, nown, A_[s].data(), B_[s].data(), C_[s].data(), d_[s].data(), periodic, xs,
                       nface, x_.data());
          for (int k = 0; k < nface; ++k)
            for (int c = 0; c < 3; ++c) h[k][c] += x_[3 * k + c];
        }
      }
    }
  }

  if (opt_.positivity && lambda > 0.0) {
    for (int k = 0; k < nface; ++k) {
      const double a = std::max(std::max(speed_[k + 2], speed_[k + 3]) * (1.0 + 1e-12), alpha_[k]);
      if (limitPositivity(q[k + 2], q[k + 3], a, lambda, g, &h[k]) < 1.0) ++stats_.limited_faces;
    }
  }
}

} // namespace suite::euler
