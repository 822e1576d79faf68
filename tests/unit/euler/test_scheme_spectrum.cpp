// Measured modified wavenumbers: the linear Pade core against Lele's formula to 1e-10; every
// flux-split scheme consistent at small w (k'dx -> w) and, for the upwind-biased ones, dissipative (Im <= 0).
#include "euler/scheme_spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace suite::euler;

TEST(SchemeSpectrum, PadeCoreMatchesLeleFormula) {
  const SchemeInfo* s = findScheme("enopade6");
  ASSERT_NE(s, nullptr);
  double worst = 0.0, worst_im = 0.0;
  for (const auto& p : measureSchemeSpectrum(*s, true, 64)) {
    worst = std::max(worst, std::abs(p.re - padeModifiedWavenumber(p.w)));
    worst_im = std::max(worst_im, std::abs(p.im));
  }
  EXPECT_LE(worst, 1e-10);
  EXPECT_LE(worst_im, 1e-10) << "the central Pade core must not dissipate";
  // The formula itself at two points: k'dx = a = 14/9 at w = pi/2, and 0 at the grid scale.
  EXPECT_NEAR(padeModifiedWavenumber(M_PI / 2), 14.0 / 9.0, 1e-15);
  EXPECT_NEAR(padeModifiedWavenumber(M_PI), 0.0, 1e-15);
}

TEST(SchemeSpectrum, SchemesConsistentAndUpwindDissipative) {
  for (const char* name : {"enopade6", "crweno5", "weno5"}) {
    const SchemeInfo* s = findScheme(name);
    ASSERT_NE(s, nullptr) << name;
    const auto spec = measureSchemeSpectrum(*s, false, 128); // shock rows: the WENO-type ones
    EXPECT_NEAR(spec[0].re, spec[0].w, 1e-5) << name;        // w = 2 pi / 128: resolved
    for (const auto& p : spec) EXPECT_LE(p.im, 1e-12) << name << " w = " << p.w;
    EXPECT_LT(spec.back().im, -0.1) << name << ": upwind rows damp the grid-scale mode";
  }
  EXPECT_THROW(measureSchemeSpectrum(*findScheme("muscl2"), true, 64), std::invalid_argument);
}
