// Options files checked before PETSc reads them (see options_file_check.hpp; the rules mirror PETSc 3.18's
// src/sys/objects/options.c).
#include "core/options_file_check.hpp"

#include <yaml.h>

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <strings.h>

namespace suite {
namespace {

constexpr long long kMaxBytes = 64LL << 20; // a run deck is a few lines; more is not an options file
constexpr size_t kMaxDepth = 32;            // files including files

std::string format(const char* fmt, ...) {
  char buf[512];
  va_list ap;
  va_start(ap, fmt);
  std::vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  return buf;
}

bool endsWith(const std::string& s, const char* tail) {
  const size_t n = std::strlen(tail);
  return s.size() >= n && s.compare(s.size() - n, n, tail) == 0;
}

// Length of the valid UTF-8 sequence starting at s[i] (>= 0x80), 0 when there is none (RFC 3629: no overlong
// forms, no surrogates, nothing above U+10FFFF).
size_t utf8SequenceLength(const std::string& s, size_t i) {
  const unsigned char c = s[i];
  size_t len = 0;
  unsigned char lo = 0x80, hi = 0xBF;
  if (c >= 0xC2 && c <= 0xDF) {
    len = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    len = 3;
    if (c == 0xE0) lo = 0xA0;
    if (c == 0xED) hi = 0x9F;
  } else if (c >= 0xF0 && c <= 0xF4) {
    len = 4;
    if (c == 0xF0) lo = 0x90;
    if (c == 0xF4) hi = 0x8F;
  }
  if (len == 0 || i + len > s.size()) return 0;
  for (size_t k = 1; k < len; ++k) {
    const unsigned char b = s[i + k];
    if (b < (k == 1 ? lo : 0x80) || b > (k == 1 ? hi : 0xBF)) return 0;
  }
  return len;
}

// PETSc's PetscToken on a line whose blanks are ' ': tokens separated by blanks; a token that begins with '"'
// runs to the next '"' (or the end of the line), without the quotes.
std::vector<std::string> petscTokens(const std::string& s) {
  std::vector<std::string> out;
  size_t i = s.find_first_not_of(' ');
  while (i != std::string::npos && i < s.size()) {
    char end = ' ';
    if (s[i] == '"') {
      end = '"';
      ++i;
    }
    const size_t j = s.find(end, i);
    out.push_back(s.substr(i, j == std::string::npos ? std::string::npos : j - i));
    if (j == std::string::npos) break;
    i = s.find_first_not_of(' ', j + 1);
  }
  return out;
}

// PETSc's PetscOptionsValidKey: a dash (or two), a letter, and not a number such as -inf or -nan.
bool isOptionName(const std::string& t) {
  if (t.size() < 2 || t[0] != '-') return false;
  const size_t k = t[1] == '-' ? 2 : 1;
  if (k >= t.size() || !std::isalpha((unsigned char)t[k])) return false;
  char* end = nullptr;
  const char* key = t.c_str() + k - 1;
  (void)std::strtod(key, &end);
  return end == key || *end == '_' || std::isalnum((unsigned char)*end);
}

OptionsLine invalidLine(const std::string& line, const std::string& why) {
  OptionsLine r;
  r.kind = OptionsLine::Invalid;
  r.problem = "'" + escapedExcerpt(line) + "' " + why;
  return r;
}

OptionsLine classifyOption(const std::string& line, const std::vector<std::string>& t) {
  if (!isOptionName(t[0]))
    return invalidLine(line, "does not begin with an option name (a dash, then a letter)");
  if (t.size() > 2)
    return invalidLine(line, "has more than one value (PETSc reads one value per option: write a list as "
                             "a,b,c, a value with blanks in double quotes)");
  if (t.size() == 2 && isOptionName(t[1]))
    return invalidLine(line, "holds two options (one option per line)");
  OptionsLine r;
  r.kind = OptionsLine::Option;
  r.name = t[0];
  if (t.size() == 2) r.value = t[1];
  return r;
}

std::string where(const yaml_mark_t& m) {
  return format("line %zu, column %zu", m.line + 1, m.column + 1);
}

// The parser's complaint with its place; a reader error (bytes that are not YAML's characters) has an offset.
std::string yamlParserProblem(const yaml_parser_t& p, const std::string& text) {
  yaml_mark_t mark = p.problem_mark;
  if (p.error == YAML_READER_ERROR) {
    const size_t off = std::min(p.problem_offset, text.size());
    const size_t nl = off ? text.rfind('\n', off - 1) : std::string::npos;
    mark.line = (size_t)std::count(text.begin(), text.begin() + (std::ptrdiff_t)off, '\n');
    mark.column = nl == std::string::npos ? off : off - nl - 1;
  }
  std::string s = where(mark) + ": YAML: " + (p.problem ? p.problem : "syntax error");
  if (p.context) s += std::string(" (") + p.context + " at " + where(p.context_mark) + ")";
  return s;
}

// What PETSc's YAML reader (PetscParseLayerYAML) takes: a mapping at the top, scalar keys, and as values a
// scalar, a mapping, or a list of scalars and mappings.
struct YamlFrame {
  bool map = true;
  bool expect_key = true;
};

std::string yamlKeyProblem(const std::vector<YamlFrame>& stack, const yaml_event_t& e) {
  if (e.type != YAML_SCALAR_EVENT && e.type != YAML_ALIAS_EVENT)
    return where(e.start_mark) + ": a key must be an option name, not a " +
           (e.type == YAML_MAPPING_START_EVENT ? "mapping" : "list");
  if (stack.size() == 1 && e.type == YAML_SCALAR_EVENT) {
    const char* key = reinterpret_cast<const char*>(e.data.scalar.value);
    if (!strcasecmp(key, "options_file") || !strcasecmp(key, "options_file_yaml"))
      return where(e.start_mark) + ": '" + key +
             "' in a YAML deck is not read by PETSc (give -options_file on the command line)";
  }
  return "";
}

std::string yamlStructureProblem(std::vector<YamlFrame>& stack, const yaml_event_t& e) {
  const bool open_map = e.type == YAML_MAPPING_START_EVENT, open_seq = e.type == YAML_SEQUENCE_START_EVENT;
  const bool leaf = e.type == YAML_SCALAR_EVENT || e.type == YAML_ALIAS_EVENT;
  if (e.type == YAML_MAPPING_END_EVENT || e.type == YAML_SEQUENCE_END_EVENT) stack.pop_back();
  if (!open_map && !open_seq && !leaf) return ""; // stream, document and end events
  if (stack.empty()) {
    if (open_map || (e.type == YAML_SCALAR_EVENT && e.data.scalar.length == 0)) { // or an empty document
      if (open_map) stack.push_back({true, true});
      return "";
    }
    return where(e.start_mark) + ": the top level of a YAML options file must be a mapping (name: value)";
  }
  YamlFrame& top = stack.back();
  if (top.map && top.expect_key) {
    top.expect_key = false;
    return yamlKeyProblem(stack, e);
  }
  if (top.map) top.expect_key = true;
  if (!top.map && open_seq) return where(e.start_mark) + ": a list inside a list is not an option value";
  if (open_map || open_seq) stack.push_back({open_map, open_map});
  return "";
}

// The bytes of a file to check; "" or why it cannot be read. *unchecked: a pipe, which PETSc alone may read.
std::string readOptionsFile(const std::string& path, std::string* bytes, bool* unchecked) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) return format("cannot be read: %s", std::strerror(errno));
  if (S_ISDIR(st.st_mode)) return "is a directory, not a file";
  *unchecked = S_ISFIFO(st.st_mode);
  if (*unchecked) return "";
  if (!S_ISREG(st.st_mode)) return "is not a regular file (a device or a socket)";
  if (st.st_size > kMaxBytes)
    return format("is %lld bytes: more than an options file (at most %lld MiB)", (long long)st.st_size,
                  kMaxBytes >> 20);
  FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return format("cannot be read: %s", std::strerror(errno));
  bytes->resize((size_t)st.st_size);
  bytes->resize(std::fread(bytes->data(), 1, bytes->size(), f));
  const bool failed = std::ferror(f);
  std::fclose(f);
  return failed ? "cannot be read: read error" : "";
}

std::string quoted(const std::string& name) {
  return "'" + escapedExcerpt(name, 200) + "'";
}

std::string checkFileTree(const std::string& arg, bool yaml_flag, std::vector<std::string>* chain);

// The files a plain options file includes, each checked in turn.
std::string checkIncluded(const std::string& path, const std::vector<IncludedFile>& included,
                          std::vector<std::string>* chain) {
  for (const IncludedFile& f : included) {
    const std::string bad = checkFileTree(f.name, f.yaml_flag, chain);
    if (!bad.empty()) return bad + format(" (included by %s line %d)", quoted(path).c_str(), f.line);
  }
  return "";
}

std::string checkFileTree(const std::string& arg, bool yaml_flag, std::vector<std::string>* chain) {
  if (arg.find("${") != std::string::npos) return ""; // PETSc substitutes variables: its own message
  const std::string path = optionsFilePath(arg);
  std::string bytes;
  bool unchecked = false;
  std::string bad = readOptionsFile(path, &bytes, &unchecked);
  if (!bad.empty()) return "options file " + quoted(path) + " " + bad;
  if (unchecked) return "";
  char real[PATH_MAX];
  const std::string id = realpath(path.c_str(), real) ? real : path;
  if (std::find(chain->begin(), chain->end(), id) != chain->end() || chain->size() >= kMaxDepth)
    return "options file " + quoted(path) + " includes itself, directly or through other files";
  std::vector<IncludedFile> included;
  bad = optionsFileIsYaml(arg, yaml_flag, bytes.substr(0, 6)) ? checkYamlOptionsText(bytes)
                                                              : checkPlainOptionsText(bytes, &included);
  if (!bad.empty()) return "options file " + quoted(path) + " " + bad;
  chain->push_back(id);
  bad = checkIncluded(path, included, chain);
  chain->pop_back();
  return bad;
}

bool isOptionsFileKey(const char* a, bool* yaml) {
  *yaml = !strcasecmp(a, "-options_file_yaml");
  return *yaml || !strcasecmp(a, "-options_file");
}

// The words PETSc reads as options: the environment variable PETSC_OPTIONS (read first), then the command line.
std::vector<std::string> optionWords(int argc, char** argv) {
  std::vector<std::string> words;
  if (const char* env = std::getenv("PETSC_OPTIONS")) words = petscTokens(env);
  for (int i = 1; i < argc; ++i) words.emplace_back(argv[i]);
  return words;
}

// Rank 0: every -options_file F / -options_file_yaml F of PETSC_OPTIONS and the command line (a missing name
// is PETSc's to report).
std::string checkCommandLine(int argc, char** argv) {
  const std::vector<std::string> words = optionWords(argc, argv);
  for (size_t i = 0; i + 1 < words.size(); ++i) {
    bool yaml = false;
    if (!isOptionsFileKey(words[i].c_str(), &yaml) || words[i + 1][0] == '-') continue;
    std::vector<std::string> chain;
    const std::string bad = checkFileTree(words[++i], yaml, &chain);
    if (!bad.empty()) return bad;
  }
  return "";
}

} // namespace

std::string escapedExcerpt(const std::string& text, size_t max_chars) {
  std::string out;
  for (size_t i = 0; i < text.size();) {
    if (out.size() >= max_chars) return out + "...";
    const unsigned char c = text[i];
    const size_t len = c >= 0x80 ? utf8SequenceLength(text, i) : 1;
    if (c < 0x20 || c == 0x7F || len == 0) {
      out += format("\\x%02X", c);
      ++i;
    } else {
      out.append(text, i, len);
      i += len;
    }
  }
  return out;
}

std::string findNonText(const std::string& s) {
  int line = 1;
  size_t line_start = 0;
  for (size_t i = 0; i < s.size();) {
    const unsigned char c = s[i];
    size_t len = 1;
    const char* what = nullptr;
    if (c == 0)
      what = "NUL";
    else if ((c < 0x20 && c != '\t' && c != '\r' && c != '\n') || c == 0x7F)
      what = "a control character";
    else if (c >= 0x80 && (len = utf8SequenceLength(s, i)) == 0)
      what = "not UTF-8";
    if (what) return format("line %d, column %zu: byte 0x%02X (%s)", line, i - line_start + 1, c, what);
    if (c == '\n') {
      ++line;
      line_start = i + 1;
    }
    i += len;
  }
  return "";
}

OptionsLine classifyOptionsLine(const std::string& line) {
  std::string s = line.substr(0, line.find('#'));
  std::replace_if(
      s.begin(), s.end(), [](char c) { return c == '\t' || c == '\r' || c == '\n'; }, ' ');
  const std::vector<std::string> t = petscTokens(s);
  if (t.empty()) return OptionsLine{};
  if (t[0][0] == '-') return classifyOption(line, t);
  if (strcasecmp(t[0].c_str(), "alias") != 0)
    return invalidLine(line, "is not an option (-name [value]), an alias (alias -new -existing), a comment "
                             "(#) or blank");
  if (t.size() != 3 || !isOptionName(t[1]) || !isOptionName(t[2]))
    return invalidLine(line, "is not an alias line (alias -new -existing)");
  OptionsLine r;
  r.kind = OptionsLine::Alias;
  r.name = t[1];
  r.value = t[2];
  return r;
}

std::string checkPlainOptionsText(const std::string& text, std::vector<IncludedFile>* included) {
  const std::string bad = findNonText(text);
  if (!bad.empty()) return "is not a text file: " + bad;
  int number = 0;
  for (size_t pos = 0; pos < text.size();) {
    size_t eol = text.find('\n', pos);
    if (eol == std::string::npos) eol = text.size();
    const OptionsLine l = classifyOptionsLine(text.substr(pos, eol - pos));
    pos = eol + 1;
    ++number;
    if (l.kind == OptionsLine::Invalid) return format("line %d: ", number) + l.problem;
    bool yaml = false;
    if (l.kind != OptionsLine::Option || !isOptionsFileKey(l.name.c_str(), &yaml)) continue;
    if (l.value.empty()) return format("line %d: %s without a file name", number, l.name.c_str());
    included->push_back({l.value, yaml, number});
  }
  return "";
}

std::string checkYamlOptionsText(const std::string& text) {
  const std::string bad = findNonText(text);
  if (!bad.empty()) return "is not a text file: " + bad;
  yaml_parser_t parser;
  if (!yaml_parser_initialize(&parser)) return "could not be parsed (libyaml: out of memory)";
  yaml_parser_set_input_string(&parser, reinterpret_cast<const unsigned char*>(text.data()), text.size());
  std::vector<YamlFrame> stack;
  std::string problem;
  for (bool done = false; !done && problem.empty();) {
    yaml_event_t e;
    if (!yaml_parser_parse(&parser, &e)) {
      problem = yamlParserProblem(parser, text);
      break;
    }
    problem = yamlStructureProblem(stack, e);
    done = e.type == YAML_STREAM_END_EVENT;
    yaml_event_delete(&e);
  }
  yaml_parser_delete(&parser);
  return problem;
}

std::string optionsFilePath(const std::string& arg) {
  return endsWith(arg, ":yaml") ? arg.substr(0, arg.size() - 5) : arg;
}

bool optionsFileIsYaml(const std::string& arg, bool yaml_flag, const std::string& head) {
  if (yaml_flag || endsWith(arg, ":yaml")) return true;
  if (endsWith(arg, ".yaml") || endsWith(arg, ".yml") || endsWith(arg, ".json")) return true;
  return head.compare(0, 6, "%YAML ") == 0 || head.compare(0, 3, "---") == 0;
}

int checkOptionsFiles(MPI_Comm comm, int argc, char** argv, std::string* message) {
  int rank = 0;
  int err = MPI_Comm_rank(comm, &rank);
  if (err) return err;
  if (rank == 0) *message = checkCommandLine(argc, argv);
  int len = (int)message->size();
  if ((err = MPI_Bcast(&len, 1, MPI_INT, 0, comm))) return err;
  message->resize((size_t)len);
  return len ? MPI_Bcast(message->data(), len, MPI_CHAR, 0, comm) : MPI_SUCCESS;
}

} // namespace suite
