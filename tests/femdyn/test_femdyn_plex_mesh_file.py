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
- supports and loads by group: -bc_fixed clamped and -bc_fixed 1 (the tag) equal the default clamp bitwise (1
  rank);
  -traction tip:0,-0.5,0 (the tip face has area 1) equals the replicated path's -tip_load 0.5 (its own load
  code, fem/beam_loads.cpp) to 1e-10;
- prescribed displacements (-bc_displacement, component subsets) on the box 10 x 1 x 1 with rollers on x = 0,
  y = 0, z = 0 (each the one component normal to it), at 1 and 2 ranks, against closed forms that P1 represents
  exactly: a traction tip:1,0,0 gives uniaxial stress, u = (x, -nu y, -nu z) / E, to 1e-12 (measured 1.8e-14),
  and /final/von_mises 1 in every cell to 1e-12;
  tip:ux=2 with StVK gives the homogeneous stretch lambda_1 = 1.2 with the lateral stretch lambda_2 of
  S_22 = 0, to 1e-12 (measured 2e-16); in a dynamic run tip:ux=0.1 ramped over 40 s (-bc_ramp; 900 steps of
  0.05 s, about 32 axial periods) ends at the static strain energy 0.5 J to 1e-3 (measured 3e-5) with at most
  5e-5 J of kinetic energy left after the ramp (measured 1.9e-5; ramped over 5 s: 8e-4);
- the suite's parallel mesh file: the 4.1 file converted at 1 and at 2 ranks (-mesh_convert) and the generated
  beam converted at 2 ranks, each read back at 1, 2 and 3 ranks (-mesh_file FILE.h5, each rank reading a block):
  the same tip history and field as the Gmsh run (or the beam run) to 1e-10 (measured: 0 at 1 rank, 8e-16
  otherwise), with the groups (rollers and a traction by group) intact;
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

import femdyn_harness as harness
from femdyn_harness import FAILS, check, rel
import h5py
import numpy as np

EXE, MAKE = sys.argv[1], sys.argv[2]
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ENV = harness.ENV
TOL = 1e-10


def launch(np_, out, *args):
    return harness.launch(EXE, np_, out, *args, timeout=300)


def run(np_, out, *args):
    return harness.run(EXE, np_, out, *args, timeout=300)


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
    # 1 rank: bitwise (at 2 ranks PT-Scotch's partition, and so the round-off, can differ from run to run)
    ref = run(1, os.path.join(d, "g_ref.h5"), *base, "-tip_load", 1)
    for spec in ("clamped", "1"):
        f = run(1, os.path.join(d, f"g_{spec}.h5"), *base, "-tip_load", 1, "-bc_fixed", spec)
        check(np.array_equal(f["final/u"][:], ref["final/u"][:]), f"-bc_fixed {spec}: the default clamp, bitwise")
    rep = run(1, os.path.join(d, "g_rep.h5"), "-beam_cells", "10,2,2", "-static", "-tip_load", 0.5, "-solver",
              "cholmod")
    f = run(2, os.path.join(d, "g_tr.h5"), *base, "-traction", "tip:0,-0.5,0")
    e = rel(f["final/u"][:], rep["final/u"][:])
    check(e <= TOL, f"-traction tip:0,-0.5,0 equals the replicated -tip_load 0.5: field {e:.1e}")


def prescribed_displacements(d):
    box = os.path.join(ROOT, "inputs", "femdyn", "cantilever_10x2x2_groups.msh")
    mesh = ["-backend", "plex", "-mesh", "file", "-mesh_file", box]
    rollers = "clamped:ux=0;y0:uy=0;z0:uz=0"
    E, nu = 1000.0, 0.3
    lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    l1 = 1.2
    e11 = (l1 * l1 - 1) / 2
    l2 = np.sqrt(1 + 2 * (-lam * e11 / (2 * lam + 2 * mu)))  # S_22 = lam (E11 + 2 E22) + 2 mu E22 = 0
    for n in (1, 2):
        f = run(n, os.path.join(d, f"uni{n}.h5"), *mesh, "-static", "-bc_displacement", rollers, "-traction",
                "tip:1,0,0", "-ksp_rtol", 1e-14)
        x, u = f["mesh/coordinates"][:], f["final/u"][:]
        e = rel(u, np.stack([x[:, 0], -nu * x[:, 1], -nu * x[:, 2]], 1) / E)
        check(e <= 1e-12, f"rollers + traction, {n} ranks: uniaxial stress u = (x, -nu y, -nu z)/E to {e:.1e}")
        vm = f["final/von_mises"][:]
        ev = float(np.abs(vm - 1.0).max())
        check(vm.shape == (240,) and ev <= 1e-12, f"rollers + traction, {n} ranks: von Mises stress 1 in every cell to {ev:.1e}")
        f = run(n, os.path.join(d, f"str{n}.h5"), *mesh, "-static", "-material", "stvk", "-bc_displacement",
                rollers + ";tip:ux=2", "-ksp_rtol", 1e-14, "-snes_rtol", 1e-14)
        x, u = f["mesh/coordinates"][:], f["final/u"][:]
        e = rel(u, np.stack([(l1 - 1) * x[:, 0], (l2 - 1) * x[:, 1], (l2 - 1) * x[:, 2]], 1))
        check(e <= 1e-12, f"StVK stretch by tip:ux=2, {n} ranks: lambda_2 = {l2:.10f} to {e:.1e}")
    f = run(2, os.path.join(d, "ramp.h5"), *mesh, "-bc_displacement", rollers + ";tip:ux=0.1", "-bc_ramp", 40,
            "-dt", 0.05, "-steps", 900, "-ksp_rtol", 1e-12)
    ke, se = f["steps/kinetic_energy"][:], f["steps/strain_energy"][:]
    left, e_se = ke[801:].max(), abs(se[-1] - 0.5) / 0.5
    check(e_se <= 1e-3 and left <= 5e-5,
          f"tip:ux=0.1 ramped over 40 s: strain energy {se[-1]:.6f} J (static 0.5, {e_se:.1e}), kinetic energy "
          f"left {left:.1e} J")


def parallel_mesh_file(files, d):
    dyn = ["-material", "stvk", "-tip_load", 2, "-dt", 0.05, "-steps", 10, "-ksp_rtol", 1e-14]
    groups = ["-static", "-bc_displacement", "clamped:ux=0;y0:uy=0;z0:uz=0", "-traction", "tip:1,0,0", "-ksp_rtol",
              1e-14]
    msh = ["-backend", "plex", "-mesh", "file", "-mesh_file", files["v41"]]
    ref = run(1, os.path.join(d, "h_ref.h5"), *msh, *dyn)
    ref_g = run(1, os.path.join(d, "h_refg.h5"), *msh, *groups)
    ref_b = run(1, os.path.join(d, "h_refb.h5"), "-backend", "plex", "-beam_cells", "10,2,2", *dyn)
    made = []
    for n, src, name in ((1, msh, "msh1"), (2, msh, "msh2"), (2, ["-backend", "plex", "-beam_cells", "10,2,2"], "beam2")):
        out = os.path.join(d, f"{name}.h5")
        p = subprocess.run(["mpiexec", "--oversubscribe", "-n", str(n), EXE, *map(str, src), "-mesh_convert", out],
                           env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=120)
        check(p.returncode == 0 and os.path.exists(out), f"-mesh_convert at {n} ranks ({name}): {p.stdout.strip()[-80:]}")
        made.append((name, out))
    for name, path in made:
        for n in (1, 2, 3):
            mesh = ["-backend", "plex", "-mesh", "file", "-mesh_file", path]
            f = run(n, os.path.join(d, f"h_{name}_{n}.h5"), *mesh, *dyn)
            r = ref_b if name == "beam2" else ref
            same = np.array_equal(f["mesh/coordinates"][:], r["mesh/coordinates"][:])
            et, eu = rel(f["steps/tip_deflection"][:], r["steps/tip_deflection"][:]), rel(f["final/u"][:], r["final/u"][:])
            msg = f"{name}.h5 read at {n} ranks: tip history {et:.1e}, field {eu:.1e} (node order kept: {same})"
            if name != "beam2":
                g = run(n, os.path.join(d, f"hg_{name}_{n}.h5"), *mesh, *groups)
                eg = rel(g["final/u"][:], ref_g["final/u"][:])
                msg += f"; rollers + traction by group {eg:.1e}"
                eu = max(eu, eg)
            check(same and max(et, eu) <= TOL, msg)
    return made[0][1]


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


def bad_inputs(files, d, h5mesh):
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
    oob, notmesh = os.path.join(d, "oob.h5"), os.path.join(d, "h_ref.h5")
    with h5py.File(h5mesh, "r") as src, h5py.File(oob, "w") as dst:
        for k, v in src.attrs.items():
            dst.attrs[k] = v
        src.copy("mesh", dst)
        t = dst["mesh/tets"][:]
        t[5, 2] = 99
        dst["mesh/tets"][...] = t
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
        (mesh(oob), "tetrahedron 5 names a node outside 0..98"),
        (mesh(notmesh), "not a mesh written by -mesh_convert"),
        (mesh(h5mesh) + ["-plex_rank_cap", 100], "above -plex_rank_cap 100"),
        (["-mesh_convert", os.path.join(d, "r.h5"), "-static"], "-mesh_convert apply to -backend plex only"),
        (mesh(v22) + ["-bc_displacement", "clamped:ux=0;clamped:ux=1"], "hold a displacement component of a shared vertex at different values"),
        (mesh(v22) + ["-bc_displacement", "clamped:uq=0"], "-bc_displacement clamped:uq=0: expected GROUP:ux=a"),
        (mesh(v22) + ["-bc_displacement", "clamped:ux=0,ux=1"], "expected GROUP:ux=a"),
        (mesh(v22) + ["-bc_displacement", "clamped:ux=0", "-dirichlet", "x=0"], "give one of them"),
        (mesh(v22)[:-3] + ["-bc_displacement", "tip:ux=1", "-steps", 2, "-checkpoint_dir", os.path.join(d, "nock")],
         "dynamic runs are not checkpointed"),
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
        prescribed_displacements(d)
        h5mesh = parallel_mesh_file(files, d)
        checkpoint_restart(files, d)
        bad_inputs(files, d, h5mesh)
    if FAILS:
        print(f"{len(FAILS)} check(s) failed")
        sys.exit(1)
    print("femdyn -backend plex on Gmsh files: all checks passed")


main()
