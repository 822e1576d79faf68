// Replay driver for the libFuzzer targets (tests/fuzz/fuzz_*.cpp), so every compiler builds and ctest runs
// them: each file of the given corpus directories is fed to LLVMFuzzerTestOneInput as it is, then with
// `-mutations N` deterministic mutations (bit flips, byte deletions and insertions, truncations, and numeric
// tokens replaced by hostile values: huge, negative, zero, nan, inf). A crash kills the process (under the
// ASan+UBSan build, any memory error or undefined behaviour does); an input that runs longer than
// `-timeout S` seconds is reported as a hang. Exit 0 only if every input returned.
//   fuzz_<name>_replay [-mutations N] [-seed S] [-timeout S] DIR_OR_FILE...
#include <algorithm>
#include <cctype>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

char g_current[512] = "";

void onAlarm(int) {
  const char msg[] = "fuzz replay: HANG (timeout) on input ";
  ssize_t r = write(2, msg, sizeof msg - 1);
  r = write(2, g_current, std::strlen(g_current));
  r = write(2, "\n", 1);
  (void)r;
  _exit(2);
}

std::vector<std::string> listInputs(const std::string& path) {
  std::vector<std::string> files;
  struct stat st;
  if (stat(path.c_str(), &st) != 0) return files;
  if (!S_ISDIR(st.st_mode)) return {path};
  if (DIR* d = opendir(path.c_str())) {
    while (dirent* e = readdir(d))
      if (e->d_name[0] != '.') files.push_back(path + "/" + e->d_name);
    closedir(d);
  }
  std::sort(files.begin(), files.end());
  return files;
}

struct Rng { // splitmix64: the same mutations on every machine
  uint64_t s;
  uint64_t next() {
    uint64_t z = (s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  size_t below(size_t n) { return n ? (size_t)(next() % n) : 0; }
};

std::string mutate(const std::string& in, Rng& rng) {
  static const char* hostile[] = {"4294967296", "2147483647", "-2147483648", "99999999999999999999",
                                  "-1",         "0",          "nan",         "inf",
                                  "-inf",       "1e308",      "-1e308",      "1e-320",
                                  "",           "\n",         " ",           "$"};
  std::string s = in;
  const int edits = 1 + (int)rng.below(4);
  for (int e = 0; e < edits; ++e) {
    switch (rng.below(6)) {
    case 0: // flip a bit
      if (!s.empty()) s[rng.below(s.size())] ^= (char)(1u << rng.below(8));
      break;
    case 1: // delete a run of bytes
      if (!s.empty()) {
        const size_t at = rng.below(s.size());
        s.erase(at, 1 + rng.below(16));
      }
      break;
    case 2: // insert random bytes
      s.insert(rng.below(s.size() + 1), std::string(1 + rng.below(4), (char)rng.below(256)));
      break;
    case 3: // truncate
      s.resize(rng.below(s.size() + 1));
      break;
    case 4: { // replace a numeric token by a hostile value
      std::vector<size_t> starts;
      for (size_t i = 0; i < s.size(); ++i)
        if ((std::isdigit((unsigned char)s[i]) || s[i] == '-') &&
            (i == 0 || !std::isalnum((unsigned char)s[i - 1])))
          starts.push_back(i);
      if (!starts.empty()) {
        const size_t at = starts[rng.below(starts.size())];
        size_t end = at + 1;
        while (end < s.size() &&
               (std::isalnum((unsigned char)s[end]) || s[end] == '.' || s[end] == '-' || s[end] == '+'))
          ++end;
        s.replace(at, end - at, hostile[rng.below(sizeof hostile / sizeof *hostile)]);
      }
      break;
    }
    default: // duplicate a line
      if (!s.empty()) {
        const size_t a = s.rfind('\n', rng.below(s.size()));
        const size_t b = s.find('\n', a == std::string::npos ? 0 : a + 1);
        const size_t from = a == std::string::npos ? 0 : a + 1,
                     to = b == std::string::npos ? s.size() : b + 1;
        s.insert(from, s.substr(from, to - from));
      }
    }
  }
  return s;
}

void runOne(const std::string& data, const std::string& label, unsigned timeout) {
  std::snprintf(g_current, sizeof g_current, "%s", label.c_str());
  alarm(timeout);
  LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(data.data()), data.size());
  alarm(0);
}

} // namespace

int main(int argc, char** argv) {
  long mutations = 1000;
  uint64_t seed = 1;
  unsigned timeout = 10;
  std::vector<std::string> inputs;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-mutations" && i + 1 < argc)
      mutations = std::atol(argv[++i]);
    else if (a == "-seed" && i + 1 < argc)
      seed = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "-timeout" && i + 1 < argc)
      timeout = (unsigned)std::atoi(argv[++i]);
    else
      for (const auto& f : listInputs(a)) inputs.push_back(f);
  }
  if (inputs.empty()) {
    std::fprintf(stderr, "fuzz replay: no input files (give corpus directories or files)\n");
    return 1;
  }
  std::signal(SIGALRM, onAlarm);
  long count = 0;
  for (const auto& path : inputs) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string data = ss.str();
    runOne(data, path, timeout);
    ++count;
    Rng rng{seed ^ std::hash<std::string>{}(path.substr(path.find_last_of('/') + 1))};
    for (long m = 0; m < mutations; ++m) {
      runOne(mutate(data, rng), path + " mutation " + std::to_string(m), timeout);
      ++count;
    }
  }
  std::printf("fuzz replay: %ld inputs from %zu corpus files, no crash, no hang\n", count, inputs.size());
  return 0;
}
