// Checks that turn hostile sizes into one clear message before any time or memory is spent:
//  - integer options beyond the 32-bit PetscInt of Debian's PETSc (PETSc's own parser wraps 3000000000 to a
//    negative number silently), and counts derived from several options (cells x unknowns, bodies, rows);
//  - a run whose estimated memory does not fit in what one node offers: the smaller of its physical memory and
//    the cgroup limit of the job (cgroup v2 memory.max, v1 memory.limit_in_bytes), shared by the ranks on it.
// The memory check (never the PetscInt checks) is overridden by the options every program shares
// (core/run_context.cpp): -memory_check false skips it, -max_memory_gib G sets the limit per node.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace suite {

// Collective. If option `name` (e.g. "-nx") was given, its text must be an integer within
// [lo, PETSC_MAX_INT]; otherwise one error naming the option, its text and the range.
PetscErrorCode checkIntOptionRange(MPI_Comm comm, const char* name, long long lo);
// Collective. The same for a comma-separated integer list option (e.g. "-beam_cells 10,2,2"): every entry.
PetscErrorCode checkIntListOptionRange(MPI_Comm comm, const char* name, long long lo);

// Collective. `count` (computed in double from the sizes the options give) must fit in PetscInt; otherwise one
// error naming `options` (e.g. "-beam_cells 100000,1000,1000"), what is counted (e.g. "free DOFs") and the
// count. No option overrides it.
PetscErrorCode checkIndexCount(MPI_Comm comm, double count, const char* what, const char* options);

// Collective. `value` (the text given for option `name`) must be one of the n `choices`; *index is its position.
// Otherwise one error for the whole job (PetscOptionsEList errors on every rank, one message per rank) naming
// the option, the text and the choices.
PetscErrorCode checkChoice(MPI_Comm comm, const char* name, const char* value, const char* const* choices,
                           int n, PetscInt* index);

// Collective. bytes_this_rank: the caller's estimate of its peak memory; `what` names the options that set it
// (e.g. "-nx 4096 -ny 4096"). Errors when the ranks sharing a node need more than the limit: 90% of the node's
// memory (nodeMemoryBytes), or -max_memory_gib; -memory_check false skips the check. The error names `what`,
// the estimate, the limit and the override options.
PetscErrorCode checkMemoryEstimate(MPI_Comm comm, double bytes_this_rank, const char* what);

// The memory this process may use on its node, in bytes: the smaller of the physical memory and every cgroup
// limit found (cgroupLimitFiles); 0 if unknown. *source (optional): "physical memory" or "cgroup limit (FILE)".
double nodeMemoryBytes(std::string* source = nullptr);
// The limit in a cgroup file (v2 memory.max, v1 memory.limit_in_bytes) in bytes; 0 when there is none: "max",
// a missing or unreadable file, text that is not a positive integer, or v1's "unlimited" (>= 2^62).
double cgroupLimitBytes(const std::string& path);
// The cgroup memory limit files of this process: the v2 and v1 files at the root of `mount`
// ("/sys/fs/cgroup"), and those of the process's own cgroup as listed in `proc_cgroup` ("/proc/self/cgroup":
// lines "0::/path" for v2, "N:memory:/path" or "N:...,memory,...:/path" for v1).
std::vector<std::string> cgroupLimitFiles(const std::string& proc_cgroup, const std::string& mount);

// "1.5 GiB", "12 MiB", "300 kiB": a byte count for messages.
std::string bytesText(double bytes);

} // namespace suite
