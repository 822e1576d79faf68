// Ideal-gas Euler equations along one direction of a 1D/2D/3D grid, for the direction-by-direction schemes:
// a state of NV = dim + 2 conserved variables in the line's frame (rho, m_n, m_t1 [, m_t2], E), where m_n is
// the momentum along the line and m_t the transverse momenta (passively advected). The flux along the line,
// the Roe-averaged eigensystem (eigenvalues u - c, u, u (shear, NV - 3 times), u + c), the HLLC flux and the
// Lax-Friedrichs flux, the Hu-Adams-Shu positivity limiter. NV = 3 is the 1D system of gas.hpp.
// References: Toro, Riemann Solvers and Numerical Methods for Fluid Dynamics, 3rd ed. (2009): eqs. (3.2),
// (3.81)-(3.82) (x-split 3D Euler, right eigenvectors), sec. 11.2 (Roe averages), sec. 10.4 (HLLC, eq.
// (10.39) star states with transverse velocities); left eigenvectors: the inverse of Toro's (3.82), as in
// Shu, ICASE report 97-65 (1997), sec. 2.3, extended by the shear rows (-v_t, e_t).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace suite::euler {

template <int NV> struct LineGas {
  static_assert(NV >= 3 && NV <= 5, "1D, 2D or 3D Euler");
  using V = std::array<double, NV>;
  using M = std::array<double, NV * NV>; // row-major

  static double kinetic(const V& q) { // (1/2) |m|^2 / rho
    double s = q[1] * q[1];
    for (int t = 2; t < NV - 1; ++t) s += q[t] * q[t];
    return 0.5 * s / q[0];
  }
  static double pressure(const V& q, double g) { return (g - 1.0) * (q[NV - 1] - kinetic(q)); }
  static V flux(const V& q, double g) {
    const double u = q[1] / q[0], p = pressure(q, g);
    V f;
    f[0] = q[1];
    f[1] = q[1] * u + p;
    for (int t = 2; t < NV - 1; ++t) f[t] = q[t] * u;
    f[NV - 1] = (q[NV - 1] + p) * u;
    return f;
  }
  // |u_n| + c (NaN-propagating).
  static double maxSpeed(const V& q, double g) {
    const double u = q[1] / q[0];
    return std::abs(u) + std::sqrt(std::abs(g * pressure(q, g) / q[0]));
  }

  struct Eigen {
    M R; // columns: right eigenvectors
    M L; // rows: left eigenvectors, L R = I
  };
  // The per-state part of the Roe average: sqrt(rho), sqrt(rho) times the velocities (u_n, u_t...), sqrt(rho) H.
  struct RoeState {
    double sr, srv[NV - 2], srH;
  };
  static RoeState roeState(const V& q, double g) {
    RoeState s;
    s.sr = std::sqrt(q[0]);
    for (int c = 0; c < NV - 2; ++c) s.srv[c] = s.sr * q[c + 1] / q[0];
    s.srH = s.sr * ((q[NV - 1] + pressure(q, g)) / q[0]);
    return s;
  }
  // Roe-averaged eigensystem between qa and qb.
  static Eigen roe(const V& qa, const V& qb, double g) { return roe(roeState(qa, g), roeState(qb, g), g); }
  static Eigen roe(const RoeState& a, const RoeState& b, double g) {
    Eigen e;
    e.R.fill(0.0);
    e.L.fill(0.0);
    roeInto(a, b, g, &e);
    return e;
  }
  // The same into *out, setting only the entries that are not zero for every state (leftZero, rightZero): the
  // others must be zero already (a reused Eigen).
  static void roeInto(const RoeState& a, const RoeState& b, double g, Eigen* out) {
    const double w = 1.0 / (a.sr + b.sr);
    double vel[NV - 2]; // u_n, u_t...
    for (int c = 0; c < NV - 2; ++c) vel[c] = (a.srv[c] + b.srv[c]) * w;
    const double H = (a.srH + b.srH) * w, u = vel[0];
    double v2 = 0.0;
    for (int c = 0; c < NV - 2; ++c) v2 += vel[c] * vel[c];
    const double c2 = std::max((g - 1.0) * (H - 0.5 * v2), 1e-300), c = std::sqrt(c2);
    const double b1 = (g - 1.0) / c2, b2 = 0.5 * b1 * v2;
    auto R = [out](int r, int col) -> double& { return out->R[r * NV + col]; };
    auto L = [out](int r, int col) -> double& { return out->L[r * NV + col]; };
    const int last = NV - 1;
    // columns 0 (u - c), 1 (u), 2.. (shear), last (u + c)
    R(0, 0) = 1.0, R(1, 0) = u - c, R(last, 0) = H - u * c;
    R(0, 1) = 1.0, R(1, 1) = u, R(last, 1) = 0.5 * v2;
    R(0, last) = 1.0, R(1, last) = u + c, R(last, last) = H + u * c;
    for (int t = 2; t < last; ++t) {
      R(t, 0) = R(t, 1) = R(t, last) = vel[t - 1];
      R(t, t) = 1.0, R(last, t) = vel[t - 1];
    }
    L(0, 0) = 0.5 * (b2 + u / c), L(0, 1) = -0.5 * (b1 * u + 1.0 / c), L(0, last) = 0.5 * b1;
    L(1, 0) = 1.0 - b2, L(1, 1) = b1 * u, L(1, last) = -b1;
    L(last, 0) = 0.5 * (b2 - u / c), L(last, 1) = -0.5 * (b1 * u - 1.0 / c), L(last, last) = 0.5 * b1;
    for (int t = 2; t < last; ++t) {
      L(0, t) = L(last, t) = -0.5 * b1 * vel[t - 1];
      L(1, t) = b1 * vel[t - 1];
      L(t, 0) = -vel[t - 1], L(t, t) = 1.0;
    }
  }
  // Entries of roe()'s L (the shear rows) and R (the shear columns) that are zero for every state.
  static constexpr bool leftZero(int i, int j) { return i >= 2 && i < NV - 1 && j != 0 && j != i; }
  static constexpr bool rightZero(int i, int j) { return j >= 2 && j < NV - 1 && i != j && i != NV - 1; }
  static V mul(const M& A, const V& v) {
    V r;
    for (int i = 0; i < NV; ++i) {
      double s = 0.0;
      for (int j = 0; j < NV; ++j) s += A[i * NV + j] * v[j];
      r[i] = s;
    }
    return r;
  }

  static V laxFriedrichs(const V& qa, const V& qb, double alpha, double g) {
    const V fa = flux(qa, g), fb = flux(qb, g);
    V h;
    for (int c = 0; c < NV; ++c) h[c] = 0.5 * (fa[c] + fb[c] - alpha * (qb[c] - qa[c]));
    return h;
  }

  // HLLC flux (Toro 2009 sec. 10.4; wave speeds of Davis, eq. (10.48)).
  static V hllc(const V& qL, const V& qR, double g) {
    const double uL = qL[1] / qL[0], uR = qR[1] / qR[0];
    const double pL = pressure(qL, g), pR = pressure(qR, g);
    const double cL = std::sqrt(g * std::max(pL, 0.0) / qL[0]), cR = std::sqrt(g * std::max(pR, 0.0) / qR[0]);
    const double SL = std::min(uL - cL, uR - cR), SR = std::max(uL + cL, uR + cR);
    const V fL = flux(qL, g), fR = flux(qR, g);
    if (SL >= 0.0) return fL;
    if (SR <= 0.0) return fR;
    const double Sm =
        (pR - pL + qL[0] * uL * (SL - uL) - qR[0] * uR * (SR - uR)) / (qL[0] * (SL - uL) - qR[0] * (SR - uR));
    const bool left = Sm >= 0.0;
    const V& q = left ? qL : qR;
    const V& f = left ? fL : fR;
    const double S = left ? SL : SR, u = left ? uL : uR, p = left ? pL : pR;
    const double k = q[0] * (S - u) / (S - Sm);
    V star, h;
    star[0] = k;
    star[1] = k * Sm;
    for (int t = 2; t < NV - 1; ++t) star[t] = k * q[t] / q[0];
    star[NV - 1] = k * (q[NV - 1] / q[0] + (Sm - u) * (Sm + p / (q[0] * (S - u))));
    for (int c = 0; c < NV; ++c) h[c] = f[c] + S * (star[c] - q[c]);
    return h;
  }

  // MUSCL-Hancock-free second-order flux at x_{j+1/2} from q[0..3] = U_{j-1} .. U_{j+2}: van Leer-limited
  // primitive slopes (rho, u_n, u_t, p), HLLC (Toro 2009 sec. 13.4 without the half-step predictor).
  static V muscl2(const V* q, double g) {
    double w[4][NV];
    for (int m = 0; m < 4; ++m) {
      w[m][0] = q[m][0];
      for (int c = 1; c < NV - 1; ++c) w[m][c] = q[m][c] / q[m][0];
      w[m][NV - 1] = pressure(q[m], g);
    }
    auto vanLeer = [](double a, double b) { return a * b > 0.0 ? 2.0 * a * b / (a + b) : 0.0; };
    double l[NV], r[NV];
    for (int c = 0; c < NV; ++c) {
      const double d0 = w[1][c] - w[0][c], d1 = w[2][c] - w[1][c], d2 = w[3][c] - w[2][c];
      l[c] = w[1][c] + 0.5 * vanLeer(d0, d1);
      r[c] = w[2][c] - 0.5 * vanLeer(d1, d2);
    }
    return hllc(fromPrim(l, g), fromPrim(r, g), g);
  }
  // w = (rho, u_n, u_t..., p) -> conserved.
  static V fromPrim(const double* w, double g) {
    V q;
    q[0] = w[0];
    double v2 = 0.0;
    for (int c = 1; c < NV - 1; ++c) {
      q[c] = w[0] * w[c];
      v2 += w[c] * w[c];
    }
    q[NV - 1] = w[NV - 1] / (g - 1.0) + 0.5 * w[0] * v2;
    return q;
  }

  // True when U_j - 2 lambda h and U_{j+1} + 2 lambda h have density and pressure >= 1e-13: then the limiter
  // below keeps h unchanged (its thresholds are <= 1e-13), so callers skip it (the common case).
  static bool sidesPositive(const V& qa, const V& qb, double lambda, double g, const V& h) {
    V a, b;
    for (int c = 0; c < NV; ++c) {
      a[c] = qa[c] - 2.0 * lambda * h[c];
      b[c] = qb[c] + 2.0 * lambda * h[c];
    }
    return a[0] >= 1e-13 && b[0] >= 1e-13 && pressure(a, g) >= 1e-13 && pressure(b, g) >= 1e-13;
  }

  // Hu, Adams & Shu, J. Comput. Phys. 242 (2013) 169, eqs. (3.6)-(3.12): blends h with the Lax-Friedrichs
  // flux so that U_j - 2 lambda h and U_{j+1} + 2 lambda h keep positive density and pressure. Returns theta.
  // *attainable (optional): whether the Lax-Friedrichs sides U_j - 2 lambda h_LF, U_{j+1} + 2 lambda h_LF have
  // density and pressure > 0, the premise of the guarantee. It holds whenever alpha >= |u| + c of both states and
  // lambda alpha <= 1/2: U_j - 2 lambda h_LF = (1 - 2 lambda alpha) U_j + lambda alpha (U_j - f_j / alpha)
  // + lambda alpha (U_{j+1} - f_{j+1} / alpha), a convex combination of admissible states (U -+ f(U) / alpha is
  // admissible for alpha >= |u| + c: Zhang & Shu, J. Comput. Phys. 229 (2010) 8918, Lemma 2); likewise the right.
  static double limitPositivity(const V& qa, const V& qb, double alpha, double lambda, double g, V* h,
                                bool* attainable = nullptr) {
    const V lf = laxFriedrichs(qa, qb, alpha, g);
    const V* q[2] = {&qa, &qb};
    const double s[2] = {-2.0 * lambda, 2.0 * lambda};
    auto side = [](const V& x, const V& f, double sc) {
      V y;
      for (int c = 0; c < NV; ++c) y[c] = x[c] + sc * f[c];
      return y;
    };
    const V lfSide[2] = {side(qa, lf, s[0]), side(qb, lf, s[1])};
    if (attainable)
      *attainable = lfSide[0][0] > 0.0 && lfSide[1][0] > 0.0 && pressure(lfSide[0], g) > 0.0 &&
                    pressure(lfSide[1], g) > 0.0;
    const double eps_rho = std::min(1e-13, std::min(lfSide[0][0], lfSide[1][0]));
    const double eps_p = std::min(1e-13, std::min(pressure(lfSide[0], g), pressure(lfSide[1], g)));
    double theta = 1.0;
    for (int k = 0; k < 2; ++k) {
      const double rh = (*q[k])[0] + s[k] * (*h)[0], rl = lfSide[k][0];
      if (rh < eps_rho) theta = std::min(theta, (rl - eps_rho) / (rl - rh));
    }
    theta = std::clamp(theta, 0.0, 1.0);
    for (int c = 0; c < NV; ++c) (*h)[c] = theta * (*h)[c] + (1.0 - theta) * lf[c];
    double theta_p = 1.0;
    for (int k = 0; k < 2; ++k) {
      const double ph = pressure(side(*q[k], *h, s[k]), g), pl = pressure(lfSide[k], g);
      if (ph < eps_p) theta_p = std::min(theta_p, (pl - eps_p) / (pl - ph));
    }
    theta_p = std::clamp(theta_p, 0.0, 1.0);
    if (theta_p < 1.0)
      for (int c = 0; c < NV; ++c) (*h)[c] = theta_p * (*h)[c] + (1.0 - theta_p) * lf[c];
    return theta * theta_p;
  }
};

} // namespace suite::euler
