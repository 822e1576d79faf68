// Run context: PETSc/MPI lifetime, shared options, unused-option check, collective stop requests.
#include "core/run_context.hpp"

#include "core/error_handler.hpp"
#include "core/options_file_check.hpp"
#include "core/option_value.hpp"
#include "core/sanitizer_defaults.hpp"

#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>

namespace suite {

volatile std::sig_atomic_t g_stop_signal = 0;

namespace {
extern "C" void onStopSignal(int sig) {
  g_stop_signal = sig;
}

// PETSc reads its viewer and convergence-reason options only during or after a solve (KSPSolve,
// SNESSolve, TSSolve, ...): at the setup-time check they are still unused and must not count as misspelled.
bool readDuringSolve(const char* name) {
  const std::string s(name);
  for (const char* suffix : {"_view", "_converged_reason", "_view_pre", "_view_solution", "_view_values"})
    if (s.size() >= std::strlen(suffix) &&
        s.compare(s.size() - std::strlen(suffix), std::string::npos, suffix) == 0)
      return true;
  return s.find("_view_") != std::string::npos || s.rfind("log_", 0) == 0;
}

std::string isoNowUtc() {
  std::time_t now = std::time(nullptr);
  std::tm tm_utc{};
  gmtime_r(&now, &tm_utc);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm_utc);
  return buf;
}

// -help: PETSc prints its generic options while PetscInitialize runs, before the app has declared any of its
// own. They are held here and printed after the app's options, under a heading (RunContext::exitCode).
std::string g_generic_help;
PetscErrorCode bufferHelp(MPI_Comm comm, const char format[], ...) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank != 0) return 0;
  va_list ap, again;
  va_start(ap, format);
  va_copy(again, ap);
  const int n = std::vsnprintf(nullptr, 0, format, ap); // whole, at any length
  va_end(ap);
  if (n > 0) {
    std::string text(static_cast<size_t>(n) + 1, '\0');
    std::vsnprintf(&text[0], text.size(), format, again);
    text.resize(static_cast<size_t>(n));
    g_generic_help += text;
  }
  va_end(again);
  return 0;
}

// The override of the memory estimate check (core/resource_checks.hpp reads them where it checks); the
// PetscInt range checks have none.
PetscErrorCode readMemoryCheckOptions(PetscOptionItems* PetscOptionsObject, PetscReal* gib) {
  PetscBool check = PETSC_TRUE;
  PetscFunctionBeginUser;
  PetscCall(suite::optionsBool(
      PetscOptionsObject, "-memory_check",
      "Refuse a run whose memory estimate exceeds the limit of its node (false: run anyway)", nullptr, check,
      &check, nullptr));
  PetscCall(
      suite::optionsReal(PetscOptionsObject, "-max_memory_gib",
                         "Memory limit per node for that check in GiB (0: 90% of the smaller of physical "
                         "memory and the cgroup limit)",
                         nullptr, *gib, gib, nullptr));
  PetscFunctionReturn(0);
}

void installStopHandlers() {
  struct sigaction sa {};
  sa.sa_handler = onStopSignal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGTERM, &sa, nullptr);
  sigaction(SIGUSR1, &sa, nullptr);
}
} // namespace

RunContext::RunContext(int* argc, char*** argv, const char* help, const char* program) : program_(program) {
  // Inside a program that already runs PETSc (the unit tests) the context uses it and leaves its end to it.
  PetscBool already = PETSC_FALSE;
  PetscInitialized(&already);
  owns_petsc_ = !already;
  // The suite's handler is pushed first so that errors while reading the command line and -options_file
  // (before PetscInitialize returns) are reported like every other error: once, without a traceback.
  keepSanitizerDefaults();
  if (owns_petsc_) {
    pushSuiteErrorHandler();
    init_error_ = startMpiAndCheckOptionsFiles(*argc, *argv);
    if (init_error_) return;
    PetscHelpPrintf = bufferHelp;
    init_error_ = PetscInitialize(argc, argv, nullptr, help);
    PetscHelpPrintf = PetscHelpPrintfDefault;
    if (init_error_) {
      finalize_mpi_ = false; // as before the options file check: a half-started PETSc is left alone
      return;
    }
  }
  petsc_up_ = true;
  t0_ = MPI_Wtime();
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank_);
  MPI_Comm_size(PETSC_COMM_WORLD, &size_);
  // Rank 0's clock is the job's start time.
  start_time_iso_ = isoNowUtc();
  char buf[32] = {0};
  std::snprintf(buf, sizeof buf, "%s", start_time_iso_.c_str());
  MPI_Bcast(buf, sizeof buf, MPI_CHAR, 0, PETSC_COMM_WORLD);
  start_time_iso_ = buf;
  init_error_ = readCommonOptions();
  installStopHandlers();
}

RunContext::~RunContext() {
  if (petsc_up_ && owns_petsc_) PetscFinalize();
  if (finalize_mpi_) MPI_Finalize();
}

// MPI is started here, before PETSc (which then leaves MPI_Finalize to the destructor), so that the options
// files are checked collectively before PetscInitialize reads them: rank 0 reads them, every rank gets the
// verdict, rank 0 prints it.
PetscErrorCode RunContext::startMpiAndCheckOptionsFiles(int argc, char** argv) {
  int up = 0, provided = 0;
  MPI_Initialized(&up);
  if (!up) {
    if (MPI_Init_thread(&argc, &argv, PETSC_MPI_THREAD_REQUIRED, &provided) != MPI_SUCCESS)
      return PETSC_ERR_MPI;
    finalize_mpi_ = true;
  }
  std::string bad;
  if (checkOptionsFiles(MPI_COMM_WORLD, argc, argv, &bad) != MPI_SUCCESS) return PETSC_ERR_MPI;
  if (bad.empty()) return 0;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0) std::fprintf(stderr, "ERROR: %s\n", bad.c_str());
  return PETSC_ERR_FILE_UNEXPECTED;
}

PetscErrorCode RunContext::readCommonOptions() {
  PetscFunctionBeginUser;
  PetscBool has_help = PETSC_FALSE, quiet = PETSC_FALSE, allow = PETSC_FALSE;
  PetscReal max_memory_gib = 0.0;
  PetscCall(PetscOptionsHasHelp(nullptr, &has_help));
  help_ = has_help;
  if (help_) PetscCall(printProgramHelp());
  PetscOptionsBegin(PETSC_COMM_WORLD, nullptr, "Run control (all programs of the suite)", nullptr);
  PetscCall(suite::optionsBool(PetscOptionsObject, "-quiet",
                               "Print no progress or info lines (errors still go to stderr)", nullptr, quiet,
                               &quiet, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-max_walltime",
                               "Stop cleanly (final output/checkpoint) after this many seconds; 0 = off",
                               nullptr, max_walltime_, &max_walltime_, nullptr));
  PetscCall(suite::optionsReal(PetscOptionsObject, "-progress_interval",
                               "Seconds of wall time between progress lines", nullptr, progress_interval_,
                               &progress_interval_, nullptr));
  PetscCall(suite::optionsBool(PetscOptionsObject, "-allow_unused_options",
                               "Do not treat unknown/unused options as an error", nullptr, allow, &allow,
                               nullptr));
  PetscCall(readMemoryCheckOptions(PetscOptionsObject, &max_memory_gib));
  PetscOptionsEnd();
  PetscCheck(max_memory_gib >= 0.0 && max_memory_gib < 1e12, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE,
             "-max_memory_gib %g: must be a finite number of GiB >= 0 (0: from the node's memory)",
             (double)max_memory_gib);
  PetscCheck(max_walltime_ >= 0.0, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE,
             "-max_walltime %g: must be >= 0 seconds (0 = no limit)", (double)max_walltime_);
  PetscCheck(progress_interval_ > 0.0, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE,
             "-progress_interval %g: must be > 0 seconds", (double)progress_interval_);
  quiet_ = quiet;
  allow_unused_ = allow;
  PetscFunctionReturn(0);
}

double RunContext::wallSeconds() const {
  return MPI_Wtime() - t0_;
}

PetscErrorCode RunContext::checkUnusedOptions() const {
  PetscFunctionBeginUser;
  PetscInt n = 0;
  char **names = nullptr, **values = nullptr;
  PetscCall(PetscOptionsLeftGet(nullptr, &n, &names, &values));
  std::string list;
  PetscInt nleft = 0;
  for (PetscInt i = 0; i < n; ++i) {
    if (readDuringSolve(names[i])) continue; // judged at the end of the run instead (see finalOptionsCheck)
    ++nleft;
    if (!list.empty()) list += ", ";
    list += std::string("-") + names[i];
    if (values[i]) list += std::string(" ") + values[i];
  }
  PetscCall(PetscOptionsLeftRestore(nullptr, &n, &names, &values));
  if (nleft > 0 && allow_unused_) {
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "WARNING: options not used by %s: %s\n", program_.c_str(),
                          list.c_str()));
  } else {
    PetscCheck(nleft == 0, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG,
               "%s: unknown or unused option(s): %s (misspelled? run with -help for the list, or pass "
               "-allow_unused_options)",
               program_.c_str(), list.c_str());
  }
  PetscFunctionReturn(0);
}

PetscErrorCode RunContext::finalOptionsCheck() const {
  PetscFunctionBeginUser;
  PetscInt n = 0;
  char **names = nullptr, **values = nullptr;
  PetscCall(PetscOptionsLeftGet(nullptr, &n, &names, &values));
  std::string list;
  for (PetscInt i = 0; i < n; ++i) list += std::string(list.empty() ? "" : ", ") + "-" + names[i];
  PetscCall(PetscOptionsLeftRestore(nullptr, &n, &names, &values));
  if (!list.empty())
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "WARNING: options never used by %s: %s\n", program_.c_str(),
                          list.c_str()));
  PetscFunctionReturn(0);
}

PetscErrorCode RunContext::stopRequested(bool* stop) const {
  PetscFunctionBeginUser;
  int local = 0;
  if (g_stop_signal) local = 1;
  if (max_walltime_ > 0.0 && rank_ == 0 && wallSeconds() >= max_walltime_) local |= 2;
  int global = 0;
  PetscCallMPI(MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_BOR, PETSC_COMM_WORLD));
  *stop = global != 0;
  if (global & 1)
    stop_reason_ = "signal";
  else if (global & 2)
    stop_reason_ = "max_walltime";
  else
    stop_reason_.clear();
  PetscFunctionReturn(0);
}

std::string RunContext::optionsText() const {
  char* all = nullptr;
  if (PetscOptionsGetAll(nullptr, &all) || !all) return "";
  std::string s(all);
  PetscFree(all);
  return s;
}

// The first lines of the buffered help, up to PETSc's own list: the program's description.
PetscErrorCode RunContext::printProgramHelp() const {
  PetscFunctionBeginUser;
  const size_t generic = g_generic_help.find("----------------------------------------");
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s\n", g_generic_help.substr(0, generic).c_str()));
  g_generic_help = generic == std::string::npos ? "" : g_generic_help.substr(generic);
  PetscFunctionReturn(0);
}

int RunContext::exitCode(PetscErrorCode ierr) const {
  if (!ierr && petsc_up_ && help_ && !g_generic_help.empty())
    ierr = PetscPrintf(PETSC_COMM_WORLD, "\nPETSc's generic options (every PETSc program):\n%s",
                       g_generic_help.c_str());
  if (!ierr && petsc_up_ && !help_) ierr = finalOptionsCheck();
  std::fflush(stdout);
  std::fflush(stderr);
  return ierr ? 1 : 0;
}

} // namespace suite
