"""An independent judge of LCP, box-LCP and MLCP answers, written for the tests with numpy alone: its own readers
of the problem files (Siconos numerics text, the suite's HDF5 format) and its own residual, sharing no code with
lib/lcp (the solvers' naturalResidual and readers), so that a bug there cannot pass unseen.

  problem = read_problem(path)            # Problem(M, q, l, u, known): dense M, bounds with +-inf
  natural_residual(problem, z)            # |z - mid(l, u, z - (M z + q))|_inf
  brute_force(problem)                    # the solution of a small box LCP by enumeration of its index sets
  stored_solution(h5, solver, k, n)       # problem k's z in an lcpbench -save_solutions file (open h5py.File)

Box LCP (Siconos: relay): find l <= z <= u with w = M z + q: w >= 0 where z = l, w <= 0 where z = u, w = 0 in
between; an LCP is l = 0, u = inf; an MLCP's equality rows are free (l = -inf, u = inf). The natural residual is
zero exactly at a solution (Facchinei & Pang 2003, sec. 1.5: the mid function of the box).

`known` holds what the data says of the solution: `z` (the suite's /z_known), or for a Siconos MLCP the trailing
values the Siconos test files carry, v and w of its complementarity rows (the variables and M z + q there).
"""
from dataclasses import dataclass, field
from itertools import product

import h5py
import numpy as np


@dataclass
class Problem:
    M: np.ndarray
    q: np.ndarray
    l: np.ndarray
    u: np.ndarray
    known: dict = field(default_factory=dict)
    comp: np.ndarray = None  # indices of the complementarity rows of an MLCP (known["v"], known["w"] refer to them)


def _numbers(path):
    """The leading numbers of a Siconos text file: every token up to the first that is not a number."""
    out = []
    for tok in open(path).read().split():
        try:
            out.append(float(tok))
        except ValueError:
            break
    return out


def _column_major(vals, n):
    return np.array(vals[: n * n], dtype=float).reshape(n, n).T


def _read_lcp_dat(path):
    """n, storage 0 (dense), rows, cols, rows cols, M (column-major), q; then lb, ub for a box LCP (relay)."""
    t = _numbers(path)
    n = int(t[0])
    if int(t[1]) != 0 or int(t[2]) != n or int(t[3]) != n:
        raise ValueError(f"{path}: not a dense {n} x {n} problem")
    k = 6  # n, storage, rows, cols, rows, cols
    M = _column_major(t[k:], n)
    q = np.array(t[k + n * n: k + n * n + n])
    rest = t[k + n * n + n:]
    if len(rest) >= 2 * n:  # relay: lb, ub
        return Problem(M, q, np.array(rest[:n]), np.array(rest[n: 2 * n]))
    return Problem(M, q, np.zeros(n), np.full(n, np.inf))


def _read_mlcp_dat(path):
    """Siconos' MLCP layout, storage type 1 (the block form both test files give): isStorageType1,
    isStorageType2, n (equalities), m (complementarities); block row starts ending at n + m; one 0/1
    complementarity flag per block; storage 0, the dimensions, M (n + m square, column-major), q. A type-2 part
    (A, B, C, D row-wise, a, b) follows when isStorageType2 is 1; then, in some files, the solution's v and w
    (m values each)."""
    t = _numbers(path)
    type1, type2, n, m = (int(x) for x in t[:4])
    if not type1:
        raise ValueError(f"{path}: only the block storage (type 1) is read here")
    N = n + m
    k = 4
    starts = []
    while True:
        starts.append(int(t[k]))
        k += 1
        if starts[-1] == N:
            break
    flags = [int(x) for x in t[k: k + len(starts) - 1]]
    k += len(starts) - 1
    if int(t[k]) != 0 or int(t[k + 1]) != N or int(t[k + 2]) != N:
        raise ValueError(f"{path}: M is not dense {N} x {N}")
    k += 5
    M = _column_major(t[k:], N)
    k += N * N
    q = np.array(t[k: k + N])
    k += N
    if type2:
        k += n * n + m * m + n * m + m * n + n + m  # the same problem in blocks A, B, C, D, a, b
    l = np.full(N, -np.inf)
    u = np.full(N, np.inf)
    for b, is_comp in enumerate(flags):
        if is_comp:
            l[starts[b]: starts[b + 1]] = 0.0
    comp = np.flatnonzero(l == 0.0)
    known = {}
    if len(t) - k >= 2 * len(comp):
        known = {"v": np.array(t[k: k + len(comp)]), "w": np.array(t[k + len(comp): k + 2 * len(comp)])}
    return Problem(M, q, l, u, known, comp)


def _read_h5(path):
    """The suite's HDF5 problem: /q, /M dense or /M_csr (indptr, indices, data), optional /l, /u, /z_known and
    the root attribute n_eq (the first n_eq variables free when no bounds are given)."""
    with h5py.File(path, "r") as f:
        q = f["q"][...].astype(float)
        n = q.size
        if "M" in f:
            M = f["M"][...].astype(float).reshape(n, n)
        else:
            g = f["M_csr"]
            indptr, indices, data = g["indptr"][...], g["indices"][...], g["data"][...]
            M = np.zeros((n, n))
            for i in range(n):
                for p in range(indptr[i], indptr[i + 1]):
                    M[i, indices[p]] += data[p]
        if "l" in f or "u" in f:
            l = f["l"][...].astype(float) if "l" in f else np.zeros(n)
            u = f["u"][...].astype(float) if "u" in f else np.full(n, np.inf)
        else:
            n_eq = int(f.attrs.get("n_eq", 0))
            l = np.concatenate([np.full(n_eq, -np.inf), np.zeros(n - n_eq)])
            u = np.full(n, np.inf)
        known = {"z": f["z_known"][...].astype(float)} if "z_known" in f else {}
    return Problem(M, q, l, u, known)


def read_problem(path):
    path = str(path)
    if path.endswith((".h5", ".hdf5")):
        return _read_h5(path)
    if "mlcp" in path.rsplit("/", 1)[-1]:
        return _read_mlcp_dat(path)
    return _read_lcp_dat(path)


def natural_residual(p, z):
    """|z - mid(l, u, z - w)|_inf with w = M z + q (inf for a z with a NaN or of the wrong size)."""
    z = np.asarray(z, dtype=float)
    if z.shape != p.q.shape or not np.all(np.isfinite(z)):
        return np.inf
    w = p.M @ z + p.q
    return float(np.max(np.abs(z - np.clip(z - w, p.l, p.u)), initial=0.0))


def brute_force(p):
    """The solutions of a small box LCP, by enumeration: every assignment of each variable to its lower bound,
    its upper bound or free (w_i = 0), the free block solved, kept when it satisfies every sign condition to
    1e-12 (3^n linear solves: n <= 8). Returns the list of solutions found (one for a P-matrix)."""
    n = p.q.size
    found = []
    for state in product((0, 1, 2), repeat=n):  # 0: at l, 1: free, 2: at u
        st = np.array(state)
        if np.any((st == 0) & ~np.isfinite(p.l)) or np.any((st == 2) & ~np.isfinite(p.u)):
            continue
        z = np.where(st == 0, p.l, np.where(st == 2, p.u, 0.0))
        free = np.flatnonzero(st == 1)
        if free.size:
            fixed = np.flatnonzero(st != 1)
            rhs = -p.q[free] - p.M[np.ix_(free, fixed)] @ z[fixed]
            try:
                z[free] = np.linalg.solve(p.M[np.ix_(free, free)], rhs)
            except np.linalg.LinAlgError:
                continue
        if natural_residual(p, z) <= 1e-12 * (1 + np.max(np.abs(p.q))):
            if not any(np.allclose(z, y, rtol=0, atol=1e-10) for y in found):
                found.append(z)
    return found


def stored_solution(f, solver, k, n):
    """Problem k's z (n values) of `solver` in an open lcpbench output written with -save_solutions: row k of
    /results/<solver>/z, whose attribute row_length is the batch's largest n."""
    z = f[f"/results/{solver}/z"]
    L = int(z.attrs["row_length"])
    return z[k * L: k * L + n]
