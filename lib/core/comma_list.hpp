// Text of option values and attributes: comma-separated lists and the exact text of a number.
#pragma once

#include <string>
#include <vector>

namespace suite {

// "a,b,,c" -> {a, b, c} (empty items dropped).
std::vector<std::string> splitCommaList(const std::string& s);
// {a, b} -> "a, b".
std::string joinCommaList(const std::vector<std::string>& v);
// The shortest text that reads back as exactly v (%.17g).
std::string exactText(double v);

} // namespace suite
