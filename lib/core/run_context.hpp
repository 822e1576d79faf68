// Run context: PETSc/MPI initialisation and finalisation (RAII), the options every app shares,
// the unused-option check, and the collective stop request (signals, -max_walltime).
// The options files of the command line are checked before PETSc reads them (core/options_file_check.hpp):
// MPI is started first, and a file that is not an options file stops the job with one ERROR line.
//
// Usage (thin main, see apps/*/main.cpp):
//   int main(int argc, char** argv) {
//     suite::RunContext ctx(&argc, &argv, help, "euler");
//     if (ctx.initError()) return ctx.exitCode(ctx.initError());
//     return ctx.exitCode(runApp(ctx));
//   }
// Every error path is collective: PetscCheck on ctx.comm() with a condition that is identical on all ranks.
// An error raised on PETSC_COMM_SELF in a multi-rank run aborts the whole job with one message
// (see error_handler.hpp).
#pragma once

#include <petscsys.h>

#include <csignal>
#include <string>

namespace suite {

class RunContext {
public:
  RunContext(int* argc, char*** argv, const char* help, const char* program);
  ~RunContext();
  RunContext(const RunContext&) = delete;
  RunContext& operator=(const RunContext&) = delete;

  PetscErrorCode initError() const { return init_error_; }
  MPI_Comm comm() const { return PETSC_COMM_WORLD; }
  int rank() const { return rank_; }
  int size() const { return size_; }
  const std::string& program() const { return program_; }
  bool quiet() const { return quiet_; }
  // True when -help was given: the app registers (and so documents) its options, then returns 0
  // without running. Call checkUnusedOptions() in either case.
  bool helpRequested() const { return help_; }
  double progressInterval() const { return progress_interval_; }
  double wallSeconds() const; // since construction
  const std::string& startTimeIso() const { return start_time_iso_; }

  // Errors (collectively) when an option was given but never queried, unless -allow_unused_options.
  // Call after all setup (every PetscOptionsBegin/End block and *SetFromOptions) has run.
  // Options that PETSc reads only during a solve (*_view, *_converged_reason, log_*) are exempt here and
  // judged by finalOptionsCheck().
  PetscErrorCode checkUnusedOptions() const;
  // At the end of a run: warns (rank 0) about options that were never used, including the solve-time ones.
  PetscErrorCode finalOptionsCheck() const;
  // Collective: true on all ranks once any rank received SIGTERM/SIGUSR1/SIGINT or -max_walltime
  // has elapsed. Cheap (one MPI_Allreduce of an int); call once per step.
  PetscErrorCode stopRequested(bool* stop) const;
  // Reason for the last positive stopRequested(): "signal SIGTERM", "max_walltime", or "".
  const std::string& stopReason() const { return stop_reason_; }
  // The whole options database as text ("-a 1 -b x ...") for provenance.
  std::string optionsText() const;
  // Maps the error code of runApp to the process exit status (0 or 1) and flushes output.
  int exitCode(PetscErrorCode ierr) const;

private:
  PetscErrorCode startMpiAndCheckOptionsFiles(int argc, char** argv);
  PetscErrorCode readCommonOptions();
  PetscErrorCode printProgramHelp() const;

  PetscErrorCode init_error_ = 0;
  bool petsc_up_ = false, owns_petsc_ = true, finalize_mpi_ = false;
  int rank_ = 0, size_ = 1;
  std::string program_;
  bool quiet_ = false, help_ = false, allow_unused_ = false;
  double max_walltime_ = 0.0, progress_interval_ = 5.0, t0_ = 0.0;
  std::string start_time_iso_;
  mutable std::string stop_reason_;
};

// Set by the signal handler; exposed for tests.
extern volatile std::sig_atomic_t g_stop_signal;

} // namespace suite
