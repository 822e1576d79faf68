// The `weno5` line kernel (lib/euler/weno5_line.hpp) against the row-by-row definition of the scheme (Lax-
// Friedrichs split fluxes of the six-cell stencil, projected on the face's Roe left eigenvectors, weno5Row for
// f+ and its mirror for f-, back with the right eigenvectors): the same fluxes bitwise, for NV = 3, 4, 5, local
// and global alpha, characteristic and component-wise, on a line with a shock and smooth parts. Also roeInto
// (the reused-storage Roe eigenvectors) against roe(), and the structural zeros leftZero / rightZero. rf-char
// upwinding (rf_char.hpp) against its row-by-row definition: the upwind WENO value of l_c f where the field's
// speeds at the two cells and the face agree in sign, the split values with alpha_c = max |lambda_c| elsewhere.
#include "euler/gas_nd.hpp"
#include "euler/rf_char.hpp"
#include "euler/row.hpp"
#include "euler/weno5.hpp"
#include "euler/weno5_line.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace suite::euler;

namespace {
constexpr double kGamma = 1.4;

// A line of n cells: a shock-like jump at the middle, smooth waves elsewhere, transverse velocities.
template <int NV> std::vector<typename LineGas<NV>::V> testLine(int n) {
  std::vector<typename LineGas<NV>::V> q(n);
  for (int m = 0; m < n; ++m) {
    const double x = (m + 0.5) / n, jump = m < n / 2 ? 1.0 : 0.125;
    double w[NV];
    w[0] = jump * (1.0 + 0.2 * std::sin(6.0 * x));
    for (int c = 1; c < NV - 1; ++c) w[c] = 0.3 * c * std::cos(5.0 * x + c) - (m < n / 2 ? 0.0 : 0.4);
    w[NV - 1] = (m < n / 2 ? 1.0 : 0.1) * (1.0 + 0.1 * std::cos(3.0 * x));
    q[m] = LineGas<NV>::fromPrim(w, kGamma);
  }
  return q;
}

// The face flux between cells k + 2 and k + 3 by the row-by-row definition.
template <int NV>
typename LineGas<NV>::V referenceFlux(const typename LineGas<NV>::V* q, double a, bool characteristic) {
  using G = LineGas<NV>;
  const typename G::Eigen e = G::roe(q[2], q[3], kGamma);
  double wp[NV][6], wm[NV][6];
  for (int m = 0; m < 6; ++m) {
    const typename G::V f = G::flux(q[m], kGamma);
    typename G::V fp, fm;
    for (int c = 0; c < NV; ++c) fp[c] = 0.5 * (f[c] + a * q[m][c]), fm[c] = 0.5 * (f[c] - a * q[m][c]);
    if (characteristic) fp = G::mul(e.L, fp), fm = G::mul(e.L, fm);
    for (int c = 0; c < NV; ++c) wp[c][m] = fp[c], wm[c][m] = fm[c];
  }
  typename G::V hc;
  for (int c = 0; c < NV; ++c) {
    const Row rp = weno5Row(wp[c]), rm = mirrorRow(weno5Row, wm[c]);
    hc[c] = rp.r / rp.b + rm.r / rm.b;
  }
  return characteristic ? G::mul(e.R, hc) : hc;
}
} // namespace

template <typename T> class Weno5LineTest : public ::testing::Test {};
template <int N> struct Nv { static constexpr int value = N; };
using Sizes = ::testing::Types<Nv<3>, Nv<4>, Nv<5>>;
TYPED_TEST_SUITE(Weno5LineTest, Sizes);

TYPED_TEST(Weno5LineTest, FluxesEqualTheRowByRowSchemeBitwise) {
  constexpr int NV = TypeParam::value;
  using G = LineGas<NV>;
  const int nface = 33;
  const auto q = testLine<NV>(nface + 5);
  Weno5Line<NV> line;
  for (bool local : {true, false})
    for (bool characteristic : {true, false}) {
      std::vector<typename G::V> h(nface);
      line.faceFluxes(q.data(), nface, 2.5, local, characteristic, false, kGamma, 1.0, h.data());
      for (int k = 0; k < nface; ++k) {
        double a = 2.5;
        if (local) {
          a = 0.0;
          for (int m = 0; m < 6; ++m) a = std::max(a, G::maxSpeed(q[k + m], kGamma));
          a *= 1.0 + 1e-12;
        }
        const typename G::V ref = referenceFlux<NV>(q.data() + k, a, characteristic);
        for (int c = 0; c < NV; ++c)
          EXPECT_EQ(h[k][c], ref[c]) << "face " << k << " component " << c << " local " << local
                                     << " characteristic " << characteristic;
      }
    }
}

TYPED_TEST(Weno5LineTest, RoeIntoReusedStorageEqualsRoeAndKeepsTheStructuralZeros) {
  constexpr int NV = TypeParam::value;
  using G = LineGas<NV>;
  const auto q = testLine<NV>(12);
  typename G::Eigen reused{};
  for (int k = 0; k + 1 < 12; ++k) {
    const typename G::Eigen e = G::roe(q[k], q[k + 1], kGamma);
    G::roeInto(G::roeState(q[k], kGamma), G::roeState(q[k + 1], kGamma), kGamma, &reused);
    for (int i = 0; i < NV; ++i)
      for (int j = 0; j < NV; ++j) {
        EXPECT_EQ(reused.L[NV * i + j], e.L[NV * i + j]);
        EXPECT_EQ(reused.R[NV * i + j], e.R[NV * i + j]);
        if (G::leftZero(i, j)) {
          EXPECT_EQ(e.L[NV * i + j], 0.0) << i << "," << j;
        }
        if (G::rightZero(i, j)) {
          EXPECT_EQ(e.R[NV * i + j], 0.0) << i << "," << j;
        }
      }
  }
}

namespace {
// rf-char face flux between cells k + 2 and k + 3 by its definition (rf_char.hpp): local alpha per field, or
// alpha_global when it is > 0.
template <int NV>
typename LineGas<NV>::V rfReference(const typename LineGas<NV>::V* q, int* mixed, double alpha_global = 0.0) {
  using G = LineGas<NV>;
  const typename G::Eigen e = G::roe(q[2], q[3], kGamma);
  double lam[6][NV], roe[NV];
  for (int m = 0; m < 6; ++m) RfChar<NV>::cellSpeeds(q[m], kGamma, lam[m]);
  RfChar<NV>::roeSpeeds(e, roe);
  typename G::V hc;
  for (int c = 0; c < NV; ++c) {
    double lf[6], lu[6], a = std::abs(roe[c]);
    for (int m = 0; m < 6; ++m) {
      const typename G::V f = G::flux(q[m], kGamma);
      lf[m] = lu[m] = 0.0;
      for (int j = 0; j < NV; ++j) lf[m] += e.L[NV * c + j] * f[j], lu[m] += e.L[NV * c + j] * q[m][j];
      a = std::max(a, std::abs(lam[m][c]));
    }
    a = alpha_global > 0.0 ? alpha_global : a * (1.0 + 1e-12);
    const bool pos = lam[2][c] > 0 && roe[c] > 0 && lam[3][c] > 0,
               neg = lam[2][c] < 0 && roe[c] < 0 && lam[3][c] < 0;
    double vp[6], vm[6];
    for (int m = 0; m < 6; ++m)
      vp[m] = pos   ? lf[m]
              : neg ? 0.0
                    : 0.5 * (lf[m] + a * lu[m]),
      vm[m] = neg   ? lf[m]
              : pos ? 0.0
                    : 0.5 * (lf[m] - a * lu[m]);
    *mixed += !pos && !neg;
    hc[c] = weno5Row(vp).r + mirrorRow(weno5Row, vm).r;
  }
  return G::mul(e.R, hc);
}
} // namespace

TYPED_TEST(Weno5LineTest, RfCharFluxesEqualTheirDefinition) {
  constexpr int NV = TypeParam::value;
  using G = LineGas<NV>;
  const int nface = 33;
  const auto q =
      testLine<NV>(nface + 5); // u changes sign across the jump: fields of both signs and mixed ones
  Weno5Line<NV> line;
  std::vector<typename G::V> h(nface);
  line.faceFluxes(q.data(), nface, 2.5, true, true, true, kGamma, 1.0, h.data());
  int mixed = 0;
  for (int k = 0; k < nface; ++k) {
    const typename G::V ref = rfReference<NV>(q.data() + k, &mixed);
    for (int c = 0; c < NV; ++c) EXPECT_EQ(h[k][c], ref[c]) << "face " << k << " component " << c;
  }
  EXPECT_GT(mixed, 0); // the Lax-Friedrichs branch is exercised
  EXPECT_LT(mixed, NV * nface);
}

namespace {
// A line of n cells with u_n = 0 on its first half (gas at rest, pressure and density waves: the fields of speed
// u split at every face there) and u_n rising from 0.5 to 1.7 on the second (u_n - c changes sign once: a few
// split faces of that field).
template <int NV> std::vector<typename LineGas<NV>::V> restAndFlowLine(int n) {
  std::vector<typename LineGas<NV>::V> q(n);
  for (int m = 0; m < n; ++m) {
    const double x = (m + 0.5) / n;
    double w[NV];
    w[0] = 1.0 + 0.3 * std::sin(7.0 * x);
    for (int c = 1; c < NV - 1; ++c) w[c] = m < n / 2 ? 0.0 : (c == 1 ? 0.5 + 2.4 * (x - 0.5) : 0.2 * c);
    w[NV - 1] = 1.0 + 0.5 * std::cos(5.0 * x);
    q[m] = LineGas<NV>::fromPrim(w, kGamma);
  }
  return q;
}
} // namespace

// The kernel's two ways with split fields (weno5_line_rf.hpp: in one loop where a line has many, face by face
// where few) and the global alpha: the fluxes of the definition, bitwise (AVX2 or SSE2, whichever this CPU runs).
TYPED_TEST(Weno5LineTest, RfCharDenseAndSparseSplitsAndGlobalAlphaEqualTheDefinitionBitwise) {
  constexpr int NV = TypeParam::value;
  using G = LineGas<NV>;
  const int nface = 64;
  const auto q = restAndFlowLine<NV>(nface + 5);
  Weno5Line<NV> line;
  std::vector<typename G::V> h(nface);
  for (double alpha : {0.0, 3.0}) { // 0: local alpha
    line.faceFluxes(q.data(), nface, alpha, alpha == 0.0, true, true, kGamma, 1.0, h.data());
    int mixed = 0;
    for (int k = 0; k < nface; ++k) {
      const typename G::V ref = rfReference<NV>(q.data() + k, &mixed, alpha);
      for (int c = 0; c < NV; ++c) EXPECT_EQ(h[k][c], ref[c]) << "face " << k << " component " << c;
    }
    EXPECT_GT(mixed, (NV - 2) * nface / 2 - 4); // the fields of speed u at rest
  }
}
