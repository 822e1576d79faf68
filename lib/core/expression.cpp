// Formulas as option values, by muParser (see expression.hpp).
#include "core/expression.hpp"

#include <muParser.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace suite {

struct Expression::Impl {
  mu::Parser parser;
  bool constant = false; // no variable used: the value below, computed once
  double value = 0.0;
  std::unique_ptr<double[]> vars; // muParser binds variables by address: storage that never moves
  size_t nvars = 0;
};

Expression::~Expression() = default;

namespace {
bool isIdentifier(const std::string& s) {
  if (s.empty() || !(std::isalpha((unsigned char)s[0]) || s[0] == '_')) return false;
  return std::all_of(s.begin(), s.end(), [](char c) { return std::isalnum((unsigned char)c) || c == '_'; });
}
std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}
} // namespace

PetscErrorCode Expression::create(MPI_Comm comm, const std::string& option, const std::string& text,
                                  const std::vector<std::string>& vars, const NamedValues& params,
                                  std::shared_ptr<const Expression>* out) {
  PetscFunctionBeginUser;
  std::shared_ptr<Expression> e(new Expression());
  e->option_ = option;
  e->text_ = text;
  e->impl_ = std::make_unique<Impl>();
  Impl& im = *e->impl_;
  im.nvars = vars.size();
  im.vars = std::make_unique<double[]>(std::max<size_t>(1, vars.size()));
  std::string failure;
  int position = -1;
  std::string token;
  try {
    for (size_t v = 0; v < vars.size(); ++v) {
      im.vars[v] = 0.0;
      im.parser.DefineVar(vars[v], &im.vars[v]);
    }
    // Debian's muParser 2.3.3 defines _pi as 3.141592653589 (13 digits: sin(_pi x) off by 1.5e-13) and _e
    // likewise: both redefined to the double nearest the constant.
    im.parser.DefineConst("_pi", M_PI);
    im.parser.DefineConst("_e", M_E);
    for (const auto& p : params) im.parser.DefineConst(p.first, p.second);
    im.parser.SetExpr(text);
    im.value = im.parser.Eval(); // parses now: a syntax error is reported here, not at the first cell
    im.constant = im.parser.GetUsedVar().empty();
  } catch (const mu::Parser::exception_type& err) {
    failure = err.GetMsg();
    position = err.GetPos();
    token = err.GetToken();
  }
  PetscCheck(!trim(text).empty(), comm, PETSC_ERR_ARG_WRONG, "Empty formula for %s", option.c_str());
  PetscCheck(failure.empty(), comm, PETSC_ERR_ARG_WRONG, "Cannot parse %s \"%s\": %s (at position %d%s%s%s)",
             option.c_str(), text.c_str(), failure.c_str(), position + 1, token.empty() ? "" : ", token '",
             token.c_str(), token.empty() ? "" : "'");
  *out = e;
  PetscFunctionReturn(0);
}

double Expression::operator()(const double* values) const {
  if (impl_->constant) return impl_->value;
  for (size_t v = 0; v < impl_->nvars; ++v) impl_->vars[v] = values[v];
  try {
    return impl_->parser.Eval();
  } catch (const mu::Parser::exception_type&) {
    return NAN; // an evaluation error (not a syntax error, checked at create) reads as a non-finite value
  }
}

PetscErrorCode parseNamedValues(MPI_Comm comm, const std::string& option, const std::string& text,
                                const std::vector<std::string>& reserved, NamedValues* out) {
  PetscFunctionBeginUser;
  out->clear();
  for (const std::string& item : splitTopLevelCommas(text)) {
    if (item.empty()) continue;
    const auto eq = item.find('=');
    PetscCheck(eq != std::string::npos, comm, PETSC_ERR_ARG_WRONG,
               "Invalid %s item \"%s\": expected name=value", option.c_str(), item.c_str());
    const std::string name = trim(item.substr(0, eq)), value = trim(item.substr(eq + 1));
    PetscCheck(isIdentifier(name), comm, PETSC_ERR_ARG_WRONG,
               "Invalid %s name \"%s\": a name starts with a letter or _ and has letters, digits and _",
               option.c_str(), name.c_str());
    const bool clash = std::find(reserved.begin(), reserved.end(), name) != reserved.end();
    PetscCheck(!clash, comm, PETSC_ERR_ARG_WRONG, "Invalid %s name \"%s\": it is a variable of the formulas",
               option.c_str(), name.c_str());
    bool twice = false;
    for (const auto& p : *out) twice = twice || p.first == name;
    PetscCheck(!twice, comm, PETSC_ERR_ARG_WRONG, "%s names \"%s\" twice", option.c_str(), name.c_str());
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(value.c_str(), &end);
    PetscCheck(!value.empty() && end && *end == '\0' && errno == 0 && std::isfinite(v), comm,
               PETSC_ERR_ARG_WRONG, "Invalid %s value \"%s\" for %s: not a finite number", option.c_str(),
               value.c_str(), name.c_str());
    out->push_back({name, v});
  }
  PetscFunctionReturn(0);
}

std::vector<std::string> splitTopLevelCommas(const std::string& text) {
  std::vector<std::string> items;
  std::string cur;
  int depth = 0;
  for (char c : text) {
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if (c == ',' && depth == 0) {
      items.push_back(trim(cur));
      cur.clear();
    } else {
      cur += c;
    }
  }
  items.push_back(trim(cur));
  return items;
}

} // namespace suite
