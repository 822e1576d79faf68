#!/usr/bin/env python3
"""femdyn -backend plex on Gmsh files (PETSc's DMPlex reader, physical groups as supports and loads).

Usage: test_femdyn_plex_mesh_file.py FEMDYN MAKE_BEAM_MSH

The files are the generator's 10x2x2 cantilever written by scripts/make-beam-msh (same vertices, numbering and
tetrahedra; groups "clamped", "tip", "beam") in Gmsh 4.1 ASCII, 2.2 ASCII and 2.2 binary, and the committed
inputs/femdyn/cantilever_10x2x2.msh without groups (the supports and the load then fall back to the planes
x = 0 and x = max).

- static StVK (tip load 1) and 10 StVK Newmark steps (tip load 2, dt 0.05) on each file at 1, 2 and 3 ranks:
  the tip deflection, the tip history and the final field equal to the replicated CHOLMOD run on -mesh beam to
  1e-10 relative (measured: at most 2e-13), with the file's node numbering in /mesh/coordinates;
- supports and loads by group: -bc_fixed clamped and -bc_fixed 1 (the tag) equal the default clamp bitwise;
  -traction tip:0,-0.5,0 (the tip face has area 1) equals the replicated path's -tip_load 0.5 (its own load
  code, fem/beam_loads.cpp) to 1e-10;
- a checkpoint written at 2 ranks restarts at 3 ranks and ends on the uninterrupted run (1e-10); a restart on
  another mesh is refused;
- bad input at 1 and 2 ranks: one ERROR line and a non-zero exit naming the file, the group or the element:
  unknown group, a volume group as a support, -bc_fixed with -dirichlet, a malformed -traction, a truncated
  file, a garbled binary file, an inverted tetrahedron, 10-node tetrahedra, TetGen input, a missing file and
  -plex_rank_cap below the file's size.
"""
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

EXE, MAKE = sys.argv[1], sys.argv[2]
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
FAILS = []
TOL = 1e-10


def check(cond, msg):
    print(("ok   " if cond else "FAIL ") + msg, flush=True)
    if not cond:
        FAILS.append(msg)


def launch(np_, out, *args):
    cmd = ["mpiexec", "--oversubscribe", "-n", str(np_), EXE, *map(str, args), "-output", out, "-quiet"]
    return subprocess.run(cmd, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=120)


def run(np_, out, *args):
    p = launch(np_, out, *args)
    if p.returncode != 0:
        raise AssertionError(f"femdyn {' '.join(map(str, args))} at {np_} ranks failed:\n{p.stdout}")
    return h5py.File(out, "r")


def rel(a, b):
    return float(np.max(np.abs(np.asarray(a) - np.asarray(b))) / np.max(np.abs(b)))


def write_p2(src, dst):
    """The 2.2 ASCII beam with 10-node tetrahedra (edge midpoints appended as nodes)."""
    lines = open(src).read().split("\n")
    i = lines.index("$Nodes")
    n = int(lines[i + 1])
    xyz = {int(l.split()[0]): np.array(l.split()[1:], float) for l in lines[i + 2:i + 2 + n]}
    j = lines.index("$Elements")
    elems, mid = [], {}
    for l in lines[j + 2:j + 2 + int(lines[j + 1])]:
        p = l.split()
        if p[1] != "4":
            elems.append(l)
            continue
        v = [int(x) for x in p[5:9]]
        extra = []
        for a, b in ((0, 1), (1, 2), (2, 0), (3, 0), (3, 2), (3, 1)):
            key = tuple(sorted((v[a], v[b])))
            if key not in mid:
                mid[key] = len(xyz) + 1
                xyz[mid[key]] = 0.5 * (xyz[v[a]] + xyz[v[b]])
            extra.append(mid[key])
        elems.append(" ".join([p[0], "11", *p[2:5], *map(str, v + extra)]))
    out = lines[:i] + ["$Nodes", str(len(xyz))] + [f"{k} {float(x[0])!r} {float(x[1])!r} {float(x[2])!r}" for k, x in sorted(xyz.items())]
    out += ["$EndNodes", "$Elements", str(len(elems))] + elems + ["$EndElements", ""]
    open(dst, "w").write("\n".join(out))


def make_meshes(d):
    files = {}
    for name, extra in (("v41", []), ("v22", ["--format", "2.2"]), ("v22b", ["--format", "2.2", "--binary"])):
        files[name] = os.path.join(d, f"beam_{name}.msh")
        subprocess.run([sys.executable, MAKE, "--cells", "10,2,2", *extra, "-o", files[name]], check=True,
                       stdout=subprocess.DEVNULL)
    files["no_groups"] = os.path.join(ROOT, "inputs", "femdyn", "cantilever_10x2x2.msh")
    return files


def equal_to_replicated(files, d):
    static = ["-material", "stvk", "-static", "-tip_load", 1, "-ksp_rtol", 1e-14]
    dynamic = ["-material", "stvk", "-tip_load", 2, "-dt", 0.05, "-steps", 10, "-newton_rtol", 1e-12,
               "-ksp_rtol", 1e-14]
    beam = ["-beam_cells", "10,2,2"]
    ref_s = run(1, os.path.join(d, "ref_s.h5"), *beam, *static[:-2], "-solver", "cholmod")
    ref_d = run(1, os.path.join(d, "ref_d.h5"), *beam, *dynamic[:-2], "-solver", "cholmod")
    xr = ref_d["mesh/coordinates"][:]
    worst = 0.0
    for name, path in files.items():
        for n in (1, 2, 3):
            mesh = ["-backend", "plex", "-mesh", "file", "-mesh_file", path]
            f = run(n, os.path.join(d, f"s_{name}_{n}.h5"), *mesh, *static)
            e_s = abs(f.attrs["tip_deflection"] - ref_s.attrs["tip_deflection"]) / abs(ref_s.attrs["tip_deflection"])
            e_su = rel(f["final/u"][:], ref_s["final/u"][:])
            g = run(n, os.path.join(d, f"d_{name}_{n}.h5"), *mesh, *dynamic)
            same_nodes = g["mesh/coordinates"].shape == xr.shape and np.abs(g["mesh/coordinates"][:] - xr).max() == 0
            e_t = rel(g["steps/tip_deflection"][:], ref_d["steps/tip_deflection"][1:])
            e_u = rel(g["final/u"][:], ref_d["final/u"][:])
            worst = max(worst, e_s, e_su, e_t, e_u)
            check(same_nodes and max(e_s, e_su, e_t, e_u) <= TOL,
                  f"{name}, {n} ranks: static tip {e_s:.1e}, field {e_su:.1e}; Newmark tip history {e_t:.1e}, "
                  f"field {e_u:.1e} vs replicated CHOLMOD on -mesh beam (file node order: {same_nodes})")
    print(f"largest difference from the replicated path: {worst:.2e}")


def groups_as_supports_and_loads(files, d):
    base = ["-backend", "plex", "-mesh", "file", "-mesh_file", files["v41"], "-static", "-ksp_rtol", 1e-14]
    ref = run(2, os.path.join(d, "g_ref.h5"), *base, "-tip_load", 1)
    for spec in ("clamped", "1"):
        f = run(2, os.path.join(d, f"g_{spec}.h5"), *base, "-tip_load", 1, "-bc_fixed", spec)
        check(np.array_equal(f["final/u"][:], ref["final/u"][:]), f"-bc_fixed {spec}: the default clamp, bitwise")
    rep = run(1, os.path.join(d, "g_rep.h5"), "-beam_cells", "10,2,2", "-static", "-tip_load", 0.5, "-solver",
              "cholmod")
    f = run(2, os.path.join(d, "g_tr.h5"), *base, "-traction", "tip:0,-0.5,0")
    e = rel(f["final/u"][:], rep["final/u"][:])
    check(e <= TOL, f"-traction tip:0,-0.5,0 equals the replicated -tip_load 0.5: field {e:.1e}")


def checkpoint_restart(files, d):
    args = ["-backend", "plex", "-mesh", "file", "-mesh_file", files["v22b"], "-material", "stvk", "-tip_load", 2,
            "-dt", 0.05, "-steps", 10, "-ksp_rtol", 1e-14]
    ck = os.path.join(d, "ck")
    full = run(2, os.path.join(d, "ck_full.h5"), *args, "-checkpoint_dir", ck, "-checkpoint_every", 5)
    rs = run(3, os.path.join(d, "ck_rs.h5"), *args, "-restart", os.path.join(ck, "femdyn_0000000005.h5"))
    et = rel(rs["steps/tip_deflection"][:], full["steps/tip_deflection"][:])
    eu = rel(rs["final/u"][:], full["final/u"][:])
    check(rs["steps/tip_deflection"].shape == (10,) and et <= TOL and eu <= TOL,
          f"checkpoint at 2 ranks, restart at 3: tip history {et:.1e}, field {eu:.1e}")
    other = args[:5] + [files["v41"]] + args[6:]
    r = launch(2, os.path.join(d, "ck_bad.h5"), *other, "-restart", os.path.join(ck, "femdyn_0000000005.h5"))
    check(r.returncode != 0 and "restart" in r.stdout and "mesh " in r.stdout, "restart on another mesh file: refused")


def bad_inputs(files, d):
    v22 = files["v22"]
    text = open(v22).read()
    trunc, garbled, inverted, p2 = (os.path.join(d, n) for n in ("trunc.msh", "garbled.msh", "inv.msh", "p2.msh"))
    open(trunc, "w").write(text[: len(text) // 2])
    raw = bytearray(open(files["v22b"], "rb").read())
    for i in range(600, len(raw), 97):
        raw[i] = (raw[i] * 7 + 13) % 256
    open(garbled, "wb").write(raw)
    lines = text.split("\n")
    k = next(i for i, l in enumerate(lines) if len(l.split()) == 9 and l.split()[1] == "4")
    p = lines[k].split()
    p[7], p[8] = p[8], p[7]
    lines[k] = " ".join(p)
    open(inverted, "w").write("\n".join(lines))
    write_p2(v22, p2)
    mesh = lambda f: ["-backend", "plex", "-mesh", "file", "-mesh_file", f, "-static", "-tip_load", 1]
    cases = [
        (mesh(v22) + ["-bc_fixed", "clampd"], "-bc_fixed: no group clampd"),
        (mesh(v22) + ["-bc_fixed", "beam"], "group beam is a volume, not a surface"),
        (mesh(v22) + ["-bc_fixed", "clamped", "-dirichlet", "x=0"], "give one of them"),
        (mesh(v22) + ["-traction", "tip:0,1"], "-traction tip:0,1: expected GROUP:tx,ty,tz"),
        (mesh(v22) + ["-traction", "top:0,1,0"], "-traction: no group top"),
        (mesh(trunc), f"-mesh_file {trunc}: PETSc's mesh reader"),
        (mesh(garbled), f"-mesh_file {garbled}: PETSc's mesh reader"),
        (mesh(inverted), "tetrahedron 1 (in the file's element order) is inverted"),
        (mesh(p2), "second-order (10-node) tetrahedra"),
        (mesh(os.path.join(ROOT, "inputs", "femdyn", "beam4_p2")), "reads Gmsh .msh files"),
        (mesh(os.path.join(d, "missing.msh")), "Cannot open"),
        (mesh(v22) + ["-plex_rank_cap", 500], "above -plex_rank_cap 500"),
    ]
    for args, expect in cases:
        for n in (1, 2):
            r = launch(n, os.path.join(d, "bad.h5"), *args)
            errors = r.stdout.count("ERROR")
            check(r.returncode != 0 and expect in r.stdout and errors == 1,
                  f"{' '.join(map(str, args[4:]))} at {n} ranks: one error ({errors}) naming it ({expect})")


def main():
    with tempfile.TemporaryDirectory() as d:
        files = make_meshes(d)
        equal_to_replicated(files, d)
        groups_as_supports_and_loads(files, d)
        checkpoint_restart(files, d)
        bad_inputs(files, d)
    if FAILS:
        print(f"{len(FAILS)} check(s) failed")
        sys.exit(1)
    print("femdyn -backend plex on Gmsh files: all checks passed")


main()
