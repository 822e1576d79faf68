#!/usr/bin/env python3
"""Hostile option values: every option a program lists in -help, tried with nan, inf, -inf, -1, 0, 1e308, 2^31,
an empty value, a missing value and a 100,000-character value (a text or choice option with nan standing for the
first seven, which it reads through the same path; a flag with nan and 0); list options (a choice list, a numeric array, a
comma-separated string or file list) also with a list of 10,000 valid entries (the first entry of the default,
else the first listed choice; a problem file for lcpbench -file); file options also with a binary file and a
truncated HDF5 file. One option at a time, appended last to a small base run (PETSc takes the last occurrence).

Usage: hostile_values.py PROGRAM NP

Each run must end within the per-run timeout (RUN_TIMEOUT s times $SUITE_TIMEOUT_SCALE) either
  - cleanly (exit 0, no ERROR line), or
  - with one clean collective error: non-zero exit (not a signal), exactly one line starting with "ERROR:" and none
    with "ERROR on rank" (every rank reads the same options, so an option error must be collective), no
    MPI_ABORT, no crash or sanitizer text;
and
  - nan given to a numeric option and 2^31 given to an integer option (PetscInt is 32-bit) are refused;
  - the 100,000-character value is never shown cut to more than 2,048 characters (a message quotes it whole,
    abbreviated, or cut by PETSc's 2,048-character error message: an option read into a fixed buffer would be cut
    at the buffer's size, 4,096 or more, without a word);
  - a failed run leaves the good output file of the base run (every hostile run would overwrite it) bitwise
    unchanged, unless its ERROR line names that file (the suite's documented "output up to step N in OUT") and
    the file is a valid HDF5 file; no run leaves a partial file (*.tmp, *.partial, *.probe) behind, but for the
    OUT.partial that lcpbench keeps, and names, when the base run's -max_walltime stops a batch.
The options are parsed from `PROGRAM BASE -help` up to the line "PETSc's generic options" for every base
configuration of the program, so a new option is covered without editing this test; an option listed by several
bases is tried with the first base that lists it. The suite prints `  -name <value>: text` (value in effect,
lists whole; core/option_text.hpp); the kind is read off the value (true/false: flag, digits: integer, a number
with '.', an exponent or inf: real, numbers with commas: array) and the lines below it (indented: choices);
Lines in PETSc's own forms (`-name: <A : B>` and `<now A : formerly B>`, its wording) are read too.
Cost: a run takes ~0.1 s of CPU but ~0.5 s of wall time (MPI start-up waits), so HOSTILE_JOBS (default 4) runs go
at a time, each in its own scratch folder with its own good file. Open MPI is told to use its shared-memory
transport (pml ob1, btl self,vader: no network probing) and to kill the other ranks of a failed job at once
(odls_base_sigkill_timeout 0; the default 1 s wait would be most of the cost of a failing run); a 1-rank run is a
singleton without a runtime daemon, in a session directory of its own (env()), and hwloc skips its PCI scan.
Prints every failing case (command line, long values abbreviated, and output tail) and a summary:
  hostile PROGRAM np=N: R runs, F failures, T s (C s CPU; ...)
"""
import hashlib
import os
import queue
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import h5py

SRC = Path(os.environ.get("SUITE_SOURCE", Path(__file__).resolve().parents[2]))
BIN = Path(os.environ.get("SUITE_BIN", SRC / "build" / "bin"))
DATA = Path(os.environ.get("SUITE_DATA", SRC.parent / "shared" / "data"))
RUN_TIMEOUT = 30.0 * float(os.environ.get("SUITE_TIMEOUT_SCALE", "1"))
JOBS = int(os.environ.get("HOSTILE_JOBS", "4"))

VALUES = ["nan", "inf", "-inf", "-1", "0", "1e308", str(2**31), ""]
# Options whose value is text (a free string, a choice) read every one of VALUES through the same path (the text
# is kept, or looked up among the choices): one non-empty text stands for them. A flag reads them through its
# parser: one invalid text and 0. Numbers (integers, reals, arrays) get every value.
VALUES_OF_KIND = {"string": ["nan", ""], "choice": ["nan", ""], "bool": ["nan", "0", ""]}
MISSING = None  # the option last on the command line, without a value
LONG = "x" * 100000  # within Linux's 128 KiB limit on one argument
LIST_ENTRIES = 10000
# The long value shown cut: a run of its x's longer than 2,048 but not all of them (a value read into a fixed
# buffer, as PETSc's PETSC_MAX_PATH_LEN of 4,096, is cut at the buffer's size; PETSc itself cuts an error message
# at 2,048 characters, and a message may abbreviate the value).
CUT = re.compile(r"x{2049,}")
# A valid entry of list options whose default is empty (generic rule: the default's first entry); a file is
# linked into each scratch folder under a short name (10,000 entries of a long path pass Linux's 128 KiB limit
# on one argument). A list that takes @LIST is also given LIST_FILE, 10,000 lines of the entry.
LINKS = {"p.dat": SRC / "inputs" / "lcpbench" / "lcp_4.dat", "bump.h5": SRC / "inputs" / "euler" / "density_bump.h5"}
LIST_ENTRY = {"-file": "p.dat"}
LIST_FILE = "entries.txt"
OUT = "out.h5"

# Base configurations: small and fast, output OUT in the scratch folder. Several per program where -help lists
# different options (euler: per -dim). The base bounds the run (few steps, -max_walltime) so that a huge value of
# one option (an end time, a step count) still ends in time.
BASES = {
    "euler": [
        ["-dim", "1", "-nx", "16", "-t_final", "0.01", "-max_steps", "4", "-max_walltime", "10", "-output", OUT],
        ["-dim", "2", "-nx", "8", "-ny", "8", "-t_final", "0.01", "-max_steps", "2", "-max_walltime", "10",
         "-output", OUT],
        ["-dim", "3", "-nx", "8", "-ny", "8", "-nz", "8", "-t_final", "0.01", "-max_steps", "2",
         "-max_walltime", "10", "-output", OUT],
        # a user's own problems: formulas (with an inflow face and a solid), a file, an obstacle preset
        ["-dim", "2", "-problem", "formula", "-ic_rho", "1.0", "-ic_p", "1.0", "-nx", "24", "-ny", "16", "-t_final", "0.01",
         "-bc_x_lo", "inflow", "-bc_x_lo_state", "1,0.1,0,1", "-solid", "0.01 - (x-0.5)^2 - (y-0.5)^2",
         "-max_steps", "2", "-max_walltime", "10", "-output", OUT],
        ["-dim", "2", "-problem", "file", "-initial_state", "bump.h5", "-t_final", "0.01", "-max_steps", "2",
         "-max_walltime", "10", "-output", OUT],
        ["-dim", "2", "-problem", "shock_cylinder", "-nx", "32", "-ny", "24", "-max_steps", "2", "-max_walltime",
         "10", "-output", OUT],
    ],
    "femdyn": [["-beam_cells", "2,1,1", "-steps", "2", "-max_walltime", "10", "-output", OUT]],
    "contact": [["-steps", "3", "-max_walltime", "10", "-output", OUT]],
    "lcpbench": [["-n", "4", "-count", "3", "-max_walltime", "10", "-output", OUT]],
    "lcpcompare": [["-n", "4", "-count", "2", "-max_walltime", "10", "-output", OUT]],
    "reorder": [["-matrix", str(DATA / "matrices" / "bcsstk01.mtx"), "-repeat", "1", "-max_walltime", "10",
                 "-output", OUT]],
}
# A file option is read only in its mode: the binary and truncated files are given in that mode too.
FILE_MODES = {"-mesh_file": ["-mesh", "file"], "-scene_file": ["-scene", "file"], "-file": ["-family", "file"],
              "-reference": ["-error"]}
FILE_WORDS = re.compile(r"file|path|mesh|restart|checkpoint|reference|matrix|deck|scene|directory|prefix", re.I)
CRASH = re.compile(r"MPI_ABORT was invoked|Segmentation fault|Caught signal|terminate called|\(core dumped\)|"
                   r"AddressSanitizer|runtime error:|LeakSanitizer|exited on signal|killed by signal")
# mpiexec's own notice that a rank exited non-zero: not the program's output.
MPIEXEC_NOTICE = re.compile(r"^-{20,}\n(Primary job  terminated normally.*?|mpiexec detected that one or more.*?)"
                            r"^-{20,}\n", re.M | re.S)
MPI_START_FAILED = re.compile(r"ompi_rte_init failed|orte_init failed|fail during orte_init|"
                              r"before MPI_INIT completed")
PARTIAL = re.compile(r"\.(tmp|partial|probe)$")


def env(cwd):
    """A 1-rank run is a singleton without a runtime daemon (ess_singleton_isolated: Open MPI 4.1 otherwise forks
    an orted for it, 0.06-0.1 CPU-s of a refused run's 0.17-0.29) in a session directory of its own scratch
    folder (orte_tmpdir_base): daemon-less singletons share one job id, so concurrent ones would share, and the
    first to finish would remove, the session directory that MPI-IO's shared-file-pointer component maps files
    in ("mca_sharedfp_sm_file_open: Error, unable to open file for mmap", 5 of 1,600 runs)."""
    return dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_odls_base_sigkill_timeout="0",
                OMPI_MCA_pml="ob1", OMPI_MCA_btl="self,vader", OMPI_MCA_ess_singleton_isolated="1",
                OMPI_MCA_orte_tmpdir_base=str(Path(cwd) / "mpi-session"), HWLOC_COMPONENTS="-pci")


def mpi(np_, prog, args):
    """At 1 rank the program runs as an MPI singleton (as `build/bin/PROG ...` typed by a user), without mpiexec's
    start-up and its wait on a failed job; at 2 ranks under mpiexec."""
    if np_ == 1:
        return [str(BIN / prog)] + args
    return ["mpiexec", "--oversubscribe", "-n", str(np_), str(BIN / prog)] + args


NUMBER = re.compile(r"[-+]?(\d+\.?\d*([eE][-+]?\d+)?|\.\d+([eE][-+]?\d+)?|inf)", re.I)


def kind_of_value(value):
    """The kind an option's value in the suite's -help line shows (bool, int, real, array or string)."""
    if value in ("true", "false"):
        return "bool"
    if re.fullmatch(r"-?\d+", value):
        return "int"
    if NUMBER.fullmatch(value):
        return "real"
    entries = value.split(",")
    if len(entries) > 1 and all(NUMBER.fullmatch(e) for e in entries):
        return "array"
    return "string"


def parse_help(text):
    """[(name, kind, help line, valid list entry or None)] of the program's own options; kind: bool, int, real,
    array, choice, string. A list option (choice list, array, comma-separated string) has a valid entry: the first
    of its default, else its first listed choice (LIST_ENTRY for some with an empty default)."""
    text = text.split("PETSc's generic options")[0]
    lines = text.splitlines()
    opts = []
    for i, line in enumerate(lines):
        choice = i + 1 < len(lines) and lines[i + 1].startswith("      ")
        m = re.match(r"^  (-[A-Za-z0-9_]+) <(.*?)>: (.*)$", line)
        if m:  # the suite's own line
            name, value, help_text = m.groups()
            kind = "choice" if choice else kind_of_value(value)
        else:  # PETSc's forms
            m = re.match(r"^  (-[A-Za-z0-9_]+)(:?) <([^>]*)>", line)
            if not m:
                continue
            name, colon, value = m.groups()
            help_text = line
            now = re.match(r"now (.*) : formerly", value)
            pair = re.match(r"(.*) : (.*)", value)
            if colon:
                kind = "bool"
            elif choice:
                kind = "choice"
            elif now:
                value = now.group(1).strip()
                kind = "int" if re.fullmatch(r"-?\d+", value) else "string"
            elif pair:
                value, kind = pair.group(1).strip(), "real"
            else:
                kind = "array"
        listed = kind == "array" or (kind in ("choice", "string") and re.search(r"comma", help_text, re.I))
        entry = None
        if listed:
            entry = value.split(",")[0] or LIST_ENTRY.get(name)
            first_choice = re.match(r"^      (\S+)  ", lines[i + 1]) if choice else None
            if not entry and first_choice:
                entry = first_choice.group(1)
        opts.append((name, kind, line, entry))
    return opts


def is_file_option(kind, line):
    return kind == "string" and FILE_WORDS.search(line) is not None


def digest(path):
    return hashlib.sha256(path.read_bytes()).hexdigest() if path.exists() else None


def leftovers(d):
    return sorted(str(p.relative_to(d)) for p in d.rglob("*") if PARTIAL.search(p.name))


def judge(rc, out, name, kind, value):
    """Why the run is not acceptable, or None."""
    if rc is None:
        return f"no exit within {RUN_TIMEOUT:.0f} s (hang)"
    if rc < 0 or rc >= 128:
        return f"killed by a signal (exit {rc})"
    errors = [ln for ln in out.splitlines() if ln.startswith("ERROR")]
    if CRASH.search(out):
        return f"crash/abort text: {CRASH.search(out).group(0)!r}"
    if value == LONG:
        cut = [len(m.group(0)) for m in CUT.finditer(out) if len(m.group(0)) != len(LONG)]
        if cut:
            return f"the {len(LONG)}-character value shown cut to {cut[0]} characters"
    if rc == 0:
        if errors:
            return "exit 0 but an ERROR line"
        if value == "nan" and kind in ("int", "real", "array"):
            return "nan accepted by a numeric option"
        if value == str(2**31) and kind == "int":
            return "2^31 accepted by a 32-bit integer option"
        return None
    if len(errors) != 1 or not errors[0].startswith("ERROR:"):
        return f"exit {rc} with {len(errors)} ERROR lines (want one 'ERROR:' line)"
    return None


def run(np_, prog, args, cwd):
    """(exit code or None on a timeout, output). A run whose MPI start-up failed (Open MPI's runtime, before
    the program's first line: seen on an overloaded machine) is not the program's answer: retried, twice at most;
    a timeout is retried once, with 3 times the limit."""
    for attempt in range(3):
        try:
            # stdout, then stderr: merged, mpiexec's forwarding of a long line can interleave the other stream
            # inside it (an ERROR line in the middle of a long stdout line)
            p = subprocess.run(mpi(np_, prog, args), cwd=cwd, env=env(cwd), stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, timeout=RUN_TIMEOUT * (3 if attempt else 1))
            text = p.stdout.decode(errors="replace") + p.stderr.decode(errors="replace")
            rc, out = p.returncode, MPIEXEC_NOTICE.sub("", text)
        except subprocess.TimeoutExpired as e:
            rc, out = None, ((e.stdout or b"") + (e.stderr or b"")).decode(errors="replace")
        # A timeout is tried once more with 3 times the limit (on an overloaded machine the runs in flight stalled
        # together for over 30 s, each fine alone): a real hang hangs again.
        if not ((rc is None and attempt == 0) or (rc != 0 and MPI_START_FAILED.search(out))):
            break
        time.sleep(1.0 + attempt)
    return rc, out


def valid_hdf5(path):
    try:
        with h5py.File(path, "r") as f:
            f.visit(lambda name: None)
        return True
    except Exception:  # noqa: BLE001 (any failure to read it: not a valid file)
        return False


def check_output(work, rc, out, pristine):
    """A failed run may only change the good output file if it says so (its ERROR line names the file, e.g.
    "output up to step 3 in out.h5") and leaves a valid HDF5 file; no run leaves a partial file."""
    good = work / OUT
    if rc not in (None, 0) and digest(good) != pristine:
        error = next((ln for ln in out.splitlines() if ln.startswith("ERROR")), "")
        if OUT not in error:
            return "a failed run changed the good output file without saying so"
        if not valid_hdf5(good):
            return "a failed run left an invalid output file"
    left = leftovers(work)
    for f in left:
        (work / f).unlink()
    # lcpbench stopped by the base run's -max_walltime keeps OUT.partial to resume from, and says so (a 10,000-entry
    # file list under the sanitizers): that file is the documented result of a stop, not a leftover
    resumable = f"flushed to {OUT}.partial; run the same command again to resume"
    if rc == 0 and resumable in out:
        left = [f for f in left if f != OUT + ".partial"]
    return f"partial files left: {left}" if left else None


class Worker:
    """A scratch folder holding the good output file of one base run (restored before every case)."""

    def __init__(self, prog, np_, base, root, k):
        self.prog, self.np, self.base = prog, np_, base + ["-quiet"]
        self.work = Path(tempfile.mkdtemp(prefix=f"w{k}_", dir=root))
        for name, target in LINKS.items():
            (self.work / name).symlink_to(target)
        rc, out = run(np_, prog, self.base, self.work)
        if rc != 0:
            sys.exit(f"base run failed (exit {rc}): {prog} {' '.join(self.base)}\n{out}")
        self.pristine_bytes = (self.work / OUT).read_bytes()
        self.pristine = digest(self.work / OUT)

    def case(self, name, kind, value, mode):
        """(command line, None or why the run is not acceptable, output)"""
        if digest(self.work / OUT) != self.pristine:
            (self.work / OUT).write_bytes(self.pristine_bytes)
        if value == "@" + LIST_FILE:
            (self.work / LIST_FILE).write_text("# hostile list\n" + f"{LIST_ENTRY.get(name, 'x')}\n" * LIST_ENTRIES)
        args = self.base + list(mode) + [name] + ([] if value is MISSING else [value])
        rc, out = run(self.np, self.prog, args, self.work)
        why = judge(rc, out, name, kind, value) or check_output(self.work, rc, out, self.pristine)
        shown = " ".join(f"<{len(a)} characters: {a[:40]}...>" if len(a) > 200 else repr(a) if a == "" or " " in a
                         else a for a in mpi(self.np, self.prog, args))
        return shown, why, out


def hostile_files(root, prog, good):
    """A binary file (a chunk of the program itself) and a truncated copy of the base run's HDF5 output."""
    binary = root / "hostile_binary.bin"
    binary.write_bytes((BIN / prog).read_bytes()[:8192])
    truncated = root / "hostile_truncated.h5"
    truncated.write_bytes(good[: max(len(good) // 2, 64)])
    return [str(binary), str(truncated)]


def options_of(np_, prog, base, cwd):
    rc, text = run(np_, prog, base + ["-help"], cwd)
    if rc != 0:
        sys.exit(f"{prog} -help failed (exit {rc}):\n{text}")
    return parse_help(text)


def cases_of(opts, seen, files):
    for name, kind, line, entry in opts:
        if name in seen:
            continue
        seen.add(name)
        for value in VALUES_OF_KIND.get(kind, VALUES) + [MISSING, LONG]:
            yield name, kind, value, ()
        if entry:
            yield name, kind, ",".join([entry] * LIST_ENTRIES), FILE_MODES.get(name, ())
            if "@LIST" in line:
                yield name, kind, "@" + LIST_FILE, FILE_MODES.get(name, ())
        if is_file_option(kind, line):
            for f in files:
                yield name, kind, f, FILE_MODES.get(name, ())


def run_base(prog, np_, base, root, seen):
    """The cases of the options this base lists first, JOBS at a time (a run mostly waits: MPI start-up)."""
    workers = queue.Queue()
    for k in range(JOBS):
        workers.put(Worker(prog, np_, base, root, k))
    w0 = workers.queue[0]
    files = hostile_files(root, prog, w0.pristine_bytes)
    cases = list(cases_of(options_of(np_, prog, base, w0.work), seen, files))

    def one(c):
        w = workers.get()
        try:
            return w.case(*c)
        finally:
            workers.put(w)

    with ThreadPoolExecutor(JOBS) as pool:
        return list(pool.map(one, cases))


def main(prog, np_):
    t0 = time.time()
    cpu0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    seen, results = set(), []
    with tempfile.TemporaryDirectory(prefix=f"hostile_{prog}_np{np_}_") as d:
        for base in BASES[prog]:
            results += run_base(prog, np_, base, Path(d), seen)
    if not seen:
        sys.exit(f"no options parsed from {prog} -help")
    failures = [(shown, why, out) for shown, why, out in results if why]
    for shown, why, out in failures:
        tail = [ln if len(ln) <= 300 else f"{ln[:200]}... ({len(ln)} characters)"
                for ln in out.strip().splitlines()[-8:]]
        print(f"FAIL [{why}] {shown}\n    " + "\n    ".join(tail))
    cpu1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = cpu1.ru_utime + cpu1.ru_stime - cpu0.ru_utime - cpu0.ru_stime
    print(f"hostile {prog} np={np_}: {len(results)} runs, {len(failures)} failures, {time.time() - t0:.0f} s "
          f"({cpu:.0f} s CPU; {len(seen)} options, {JOBS} runs at a time, {RUN_TIMEOUT:.0f} s limit per run)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], int(sys.argv[2])))
