// Scheme registry (see schemes.hpp).
#include "euler/schemes.hpp"

#include "euler/crweno5.hpp"
#include "euler/crweno_cu6.hpp"
#include "euler/enopade6.hpp"
#include "euler/weno5.hpp"

namespace suite::euler {

namespace {
const SchemeInfo kSchemes[] = {
    {"enopade6", "6th-order Pade core, CRWENO-CU6 / CRWENO5-Z rows on lines with discontinuities (ENO-Pade)",
     true, true, false, padeRow, enoPadeBlendRow, central6Row, weno5Row, 6, true},
    {"crweno5",
     "5th-order compact-reconstruction WENO, Henrick-mapped weights (Ghosh & Baeder 2012; Henrick et al. "
     "2005)",
     true, false, false, crweno5MappedRow, crweno5MappedRow, weno5Row, weno5Row, 5, true},
    {"weno5", "5th-order WENO-Z, explicit (Jiang & Shu 1996; Borges et al. 2008)", false, false, false,
     weno5Row, weno5Row, weno5Row, weno5Row, 5, true},
    {"muscl2", "2nd-order MUSCL (van Leer limiter) + HLLC", false, false, true, nullptr, nullptr, nullptr,
     nullptr, 2, true},
};
} // namespace

const SchemeInfo* findScheme(const std::string& name) {
  for (const auto& s : kSchemes)
    if (name == s.name) return &s;
  return nullptr;
}

std::vector<const SchemeInfo*> allSchemes() {
  std::vector<const SchemeInfo*> out;
  for (const auto& s : kSchemes) out.push_back(&s);
  return out;
}

std::string schemeNames() {
  std::string out;
  for (const auto& s : kSchemes) out += (out.empty() ? "" : ", ") + std::string(s.name);
  return out;
}

} // namespace suite::euler
