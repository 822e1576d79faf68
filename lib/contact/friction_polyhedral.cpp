// Friction model "polyhedral": the linearised cone LCP (Lacoursiere, SIGRAD 2003, Eq. 6; Stewart & Trinkle
// 1996; Anitescu & Potra 1997) with d directions per contact: unknowns [lambda_n, beta, gamma],
//   D^T v + e gamma >= 0 _|_ beta >= 0,   mu lambda_n - e^T beta >= 0 _|_ gamma >= 0,
// with a compliance eps gamma on the cone rows (strictly copositive matrix), equilibrated by a diagonal
// scaling and solved by the -polyhedral_solvers chain (Lemke first; every answer verified on the unscaled
// problem). With mu = 0 it is the plain LCP of "none".
#include "contact/box_lcp.hpp"

#include <cmath>

namespace suite::contact {

lcp::Problem polyhedralLcp(const lcp::Mat& A, const lcp::Vec& b, int nc, int d, double mu) {
  const int m = nc * (2 + d), k = nc * (1 + d);
  lcp::Mat M = lcp::Mat::Zero(m, m);
  lcp::Vec q = lcp::Vec::Zero(m);
  M.topLeftCorner(k, k) = A;
  q.head(k) = b;
  for (int i = 0; i < nc; ++i) {
    M(k + i, i) = mu;
    for (int j = 0; j < d; ++j) {
      M(nc + i * d + j, k + i) = 1.0;
      M(k + i, nc + i * d + j) = -1.0;
    }
  }
  return lcp::makeLcp(M, q, "polyhedral");
}

lcp::Vec polyhedralScaling(const lcp::Problem& p, int nc, int d) {
  const int k = nc * (1 + d);
  lcp::Vec s(p.size());
  for (int r = 0; r < k; ++r) s[r] = p.M(r, r) > 0 ? 1.0 / std::sqrt(p.M(r, r)) : 1.0;
  for (int i = 0; i < nc; ++i) {
    double a = 0.0; // gamma_i couples to beta_ij with unit entries: scale it by the mean sqrt(A_bb)
    for (int j = 0; j < d; ++j) a += 1.0 / s[nc + i * d + j];
    s[k + i] = a / d;
  }
  return s;
}

namespace {
class PolyhedralFriction : public FrictionFormulation {
public:
  explicit PolyhedralFriction(const StepperOptions& o)
      : o_(o),
        chain_(o.polyhedral_solvers.empty() ? std::vector<std::string>{o.lcp_solver} : o.polyhedral_solvers) {
  }
  // nc normal rows, then d directions per contact (contact-major) at angles 2 pi j / d from t1.
  std::vector<ConstraintRow> rows(const std::vector<Contact>& cs) const override {
    const int nc = (int)cs.size(), d = o_.polyhedral_directions;
    std::vector<ConstraintRow> rows;
    for (int i = 0; i < nc; ++i) rows.push_back({i, cs[i].n, true});
    for (int i = 0; i < nc; ++i)
      for (int j = 0; j < d; ++j) {
        const double a = 2 * M_PI * j / d;
        rows.push_back({i, std::cos(a) * cs[i].t1 + std::sin(a) * cs[i].t2, false});
      }
    return rows;
  }
  bool impulses(const ContactStep& step, const DelassusSystem& sys, ChainSolve& solver, Impulses* out,
                StepStats* st) const override;

private:
  lcp::Problem problem(const DelassusSystem& sys, int nc) const;
  const StepperOptions o_;
  const std::vector<std::string> chain_;
};

// Eq. 6 with the compliance eps_i = gamma_reg / mean(A_bb) of contact i on its cone row.
lcp::Problem PolyhedralFriction::problem(const DelassusSystem& sys, int nc) const {
  const int d = o_.polyhedral_directions, k = nc * (1 + d);
  lcp::Problem p = polyhedralLcp(sys.A, sys.b, nc, d, o_.mu);
  if (o_.polyhedral_gamma_reg > 0)
    for (int i = 0; i < nc; ++i) {
      double abb = 0.0;
      for (int j = 0; j < d; ++j) abb += sys.A(nc + i * d + j, nc + i * d + j) / d;
      p.M(k + i, k + i) = o_.polyhedral_gamma_reg / abb;
    }
  return p;
}

bool PolyhedralFriction::impulses(const ContactStep& step, const DelassusSystem& sys, ChainSolve& solver,
                                  Impulses* out, StepStats* st) const {
  const int nc = (int)step.contacts.size(), d = o_.polyhedral_directions, k = nc * (1 + d);
  const lcp::Problem p = problem(sys, nc);
  lcp::Vec scale, z;
  if (o_.polyhedral_scaling) scale = polyhedralScaling(p, nc, d);
  if (!solver.solve(p, chain_, o_.polyhedral_scaling ? &scale : nullptr, nullptr, &z)) return false;
  st->rows = p.size();
  out->z = z.head(k);
  out->lambda.assign(nc, Vec3::Zero());
  for (int i = 0; i < nc; ++i) {
    out->lambda[i][0] = z[i];
    for (int j = 0; j < d; ++j) {
      const double a = 2 * M_PI * j / d;
      out->lambda[i][1] += z[nc + i * d + j] * std::cos(a);
      out->lambda[i][2] += z[nc + i * d + j] * std::sin(a);
    }
  }
  return true;
}
} // namespace

std::unique_ptr<FrictionFormulation> makePolyhedralFriction(const StepperOptions& o) {
  if (!(o.mu > 0)) return makeNoFriction(o);
  return std::make_unique<PolyhedralFriction>(o);
}

} // namespace suite::contact
