// -scheme_spectrum N: instead of a flow, measure the chosen scheme's modified wavenumber on an N-point periodic
// grid (lib/euler/scheme_spectrum.hpp), smooth and shock rows, print a table and write
// /scheme_spectrum/{w, smooth_re, smooth_im, shock_re, shock_im} (and the exact Pade curve) to -output.
#include "euler_run.hpp"

#include "euler/schemes.hpp"

#include "core/log.hpp"
#include "core/run_summary.hpp"
#include "euler/scheme_spectrum.hpp"

#include <exception>

namespace euler_app {

PetscErrorCode EulerRun::schemeSpectrum() {
  PetscFunctionBeginUser;
  scheme_ = suite::euler::findScheme(opt_.scheme); // a registered name (checked when read)
  const int n = (int)opt_.scheme_spectrum;
  PetscCheck(n >= 8 && n % 2 == 0 && n <= 1 << 20, ctx_.comm(), PETSC_ERR_ARG_OUTOFRANGE,
             "Invalid -scheme_spectrum %d: an even number of points in [8, 2^20]", n);
  PetscCheck(!scheme_->state_riemann, ctx_.comm(), PETSC_ERR_ARG_WRONG,
             "-scheme_spectrum: scheme %s reconstructs states (HLLC), it has no flux rows to analyse",
             scheme_->name);
  std::vector<suite::euler::SpectrumPoint> smooth, shock;
  try { // identical on every rank (serial analysis, replicated)
    smooth = suite::euler::measureSchemeSpectrum(*scheme_, true, n);
    shock = suite::euler::measureSchemeSpectrum(*scheme_, false, n);
  } catch (const std::exception& e) {
    SETERRQ(ctx_.comm(), PETSC_ERR_LIB, "-scheme_spectrum: %s", e.what());
  }
  const size_t m = smooth.size();
  std::vector<double> cols[6];
  for (auto& c : cols) c.resize(m);
  PetscCall(suite::logInfo(ctx_.comm(), quiet(), "%-10s %-12s %-12s %-12s %-12s %-12s", "k dx", "smooth re",
                           "smooth im", "shock re", "shock im", "Pade exact"));
  for (size_t i = 0; i < m; ++i) {
    cols[0][i] = smooth[i].w, cols[1][i] = smooth[i].re, cols[2][i] = smooth[i].im;
    cols[3][i] = shock[i].re, cols[4][i] = shock[i].im,
    cols[5][i] = suite::euler::padeModifiedWavenumber(smooth[i].w);
    if (m <= 64 || i % (m / 32) == 0 || i + 1 == m)
      PetscCall(suite::logInfo(ctx_.comm(), quiet(), "%-10.5f %-12.6f %-12.6f %-12.6f %-12.6f %-12.6f",
                               cols[0][i], cols[1][i], cols[2][i], cols[3][i], cols[4][i], cols[5][i]));
  }
  if (!opt_.output.empty()) PetscCall(writeSchemeSpectrum(n, cols));
  std::vector<std::string> written;
  if (!opt_.output.empty()) written.push_back(opt_.output);
  PetscCall(suite::logRunSummary(ctx_, "completed",
                                 "scheme spectrum of " + opt_.scheme + " at " + std::to_string(n) + " points",
                                 written));
  PetscFunctionReturn(0);
}

// /scheme_spectrum/{w, smooth_re, smooth_im, shock_re, shock_im, pade_exact} (cols[0..5]) into -output.
PetscErrorCode EulerRun::writeSchemeSpectrum(int n, const std::vector<double> cols[6]) {
  PetscFunctionBeginUser;
  const size_t m = cols[0].size();
  PetscCall(out_.open(ctx_.comm(), opt_.output));
  PetscCall(out_.writeProvenance(ctx_));
  PetscCall(out_.writeAttribute("/", "scheme", opt_.scheme));
  PetscCall(out_.writeAttribute("/", "scheme_spectrum_points", (long long)n));
  const char* names[6] = {"w", "smooth_re", "smooth_im", "shock_re", "shock_im", "pade_exact"};
  for (int c = 0; c < 6; ++c)
    PetscCall(out_.writeReplicated(std::string("/scheme_spectrum/") + names[c], cols[c].data(), {m}, ""));
  PetscCall(out_.writeAttribute("/", "status", "completed"));
  PetscCall(out_.commit(&ctx_));
  PetscFunctionReturn(0);
}

} // namespace euler_app
