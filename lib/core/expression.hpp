// Formulas given as option values (the Euler app's initial states, boundary states and solid bodies): parsed
// and evaluated by muParser (Debian's libmuparser-dev; https://beltoforion.de/en/muparser), not by a parser
// of the suite's own. The syntax is muParser's: + - * / ^, comparisons < <= > >= == !=, && ||, the ternary
// c ? a : b (piecewise states), sin cos tan asin acos atan sinh cosh tanh exp ln log10 sqrt abs sign rint
// min max sum avg, the constants _pi and _e (to double precision). Variables are named by the caller (x, y, z, t); named constants
// come from a "name=value,name=value" list (-ic_param). Every check is collective by construction: each rank
// parses the same text and reaches the same verdict.
#pragma once

#include <petscsys.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace suite {

using NamedValues = std::vector<std::pair<std::string, double>>;

class Expression {
public:
  // Compiles `text`, the value of `option`, over the variables `vars` and the constants `params`. A syntax
  // error or an unknown name is one error naming the option, the position (1-based) and the offending token.
  static PetscErrorCode create(MPI_Comm comm, const std::string& option, const std::string& text,
                               const std::vector<std::string>& vars, const NamedValues& params,
                               std::shared_ptr<const Expression>* out);
  ~Expression();
  Expression(const Expression&) = delete;
  Expression& operator=(const Expression&) = delete;

  // The value at `values` (one per variable, in the order of create's vars). Not thread-safe (one parser).
  double operator()(const double* values) const;
  const std::string& option() const { return option_; }
  const std::string& text() const { return text_; }

private:
  Expression() = default;
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string option_, text_;
};

// "a=1,b=2.5" -> {{"a", 1}, {"b", 2.5}}: names are identifiers ([A-Za-z_][A-Za-z0-9_]*) other than `reserved`
// (the variables), each once; values are whole numbers in C syntax. Errors name `option` and the item.
PetscErrorCode parseNamedValues(MPI_Comm comm, const std::string& option, const std::string& text,
                                const std::vector<std::string>& reserved, NamedValues* out);

// Splits a comma-separated list at the commas outside parentheses ("1, min(y,2), 0" -> 3 items), items
// trimmed of blanks.
std::vector<std::string> splitTopLevelCommas(const std::string& text);

} // namespace suite
