// femdyn -backend plex: the distributed run (femdyn_plex.cpp), its supports and loads by group
// (femdyn_plex_groups.cpp) and its HDF5 files (femdyn_plex_io.cpp). The mesh as a distributed DMPlex: the
// generated beam (fem/plex_beam.hpp) or a Gmsh file (fem/plex_mesh_file.hpp); P1 linear, StVK or corotational
// elastodynamics (fem/plex_elasticity.hpp), Newmark or generalized-alpha with Rayleigh damping + SNES on
// distributed Vecs (fem/plex_newmark.hpp). No rank
// holds a global-size array after the distribution: the beam is generated in slabs and repartitioned (a file
// is read on rank 0, then distributed), the state and the loads are distributed,
// the tip mean is reduced, and output and checkpoints are written collectively in the natural node numbering
// (fem/plex_natural.hpp: the replicated path's numbering, each rank a block of rows), so that a checkpoint
// written at P ranks restarts at Q. Options this path does not have are refused by name.
#pragma once

#include "fem/plex_natural.hpp"
#include "fem/plex_newmark.hpp"
#include "femdyn_run.hpp"
#include "io/h5_output.hpp"

#include <memory>
#include <vector>

namespace suite {
class H5Input;
} // namespace suite

namespace femdyn_app {

// The supports, the surface loads and the group whose mean -u_y is the reported tip deflection.
struct PlexModelGroups {
  std::vector<suite::fem::PlexPrescribed> held; // -bc_fixed, -bc_displacement or the -dirichlet clamp
  std::vector<suite::fem::PlexSurfaceLoad> loads;
  suite::fem::PlexGroup tip;
};
PetscErrorCode plexSupportsAndLoads(DM dm, const Options& o, PlexModelGroups* m);

struct PlexStep {
  double time, tip, wall, cpu, kinetic, strain;
  long long newton, linear;
};

class PlexRun {
public:
  PlexRun(const suite::RunContext& ctx, const Options& o, suite::CheckpointPolicy& policy)
      : ctx_(ctx), o_(o), policy_(policy) {}
  ~PlexRun();
  PetscErrorCode setup();
  // -mesh_convert: the mesh (generated or read) written as the suite's parallel mesh file.
  PetscErrorCode convertMesh();
  // The static solve or the time steps (from a restart's step on), then the output.
  PetscErrorCode solve();

private:
  PetscErrorCode checkLocalDofs() const;
  PetscErrorCode createMesh(std::vector<PetscInt>* vertex_node, long long* nodes);
  PetscErrorCode timeSteps();
  PetscErrorCode afterStep(long long step, bool* stop);
  // femdyn_plex_io.cpp
  PetscErrorCode write();
  // -snapshot_every: /snapshots/NNNNNN/{u, von_mises} in the output file (open from the first snapshot on).
  PetscErrorCode snapshot();
  PetscErrorCode writeCells(suite::H5Output& out, const char* dataset,
                            const std::vector<double>& values) const;
  PetscErrorCode writeRunAttributes(suite::H5Output& out) const;
  PetscErrorCode writeHistory(suite::H5Output& out) const;
  // held: the prescribed DOFs' values (null: 0 there)
  PetscErrorCode writeNatural(suite::H5Output& out, const char* dataset, Vec plex,
                              const std::vector<double>* held = nullptr) const;
  PetscErrorCode writeMesh(suite::H5Output& out) const;
  PetscErrorCode writeCheckpoint(long long step);
  PetscErrorCode readCheckpoint(const std::string& path);
  PetscErrorCode readHistory(const suite::H5Input& in, long long step);
  PetscErrorCode readNatural(const suite::H5Input& in, const char* dataset, Vec plex) const;

  const suite::RunContext& ctx_;
  const Options& o_;
  suite::CheckpointPolicy& policy_;
  DM dm_ = nullptr;
  suite::fem::PlexNewmark nm_;
  suite::fem::PlexNaturalOrder nat_;
  PlexModelGroups groups_;
  long long nv_ = 0, nc_ = 0;
  PetscInt ndof_ = 0;
  std::vector<PlexStep> steps_; // accepted steps so far (a restart's history first)
  bool restarted_ = false;
  suite::fem::PlexStepStats stat_;
  double tip_ = 0, tip_ux_ = 0, setup_s_ = 0, solve_s_ = 0;
  std::string status_ = "completed";
  std::unique_ptr<suite::H5Output> out_; // the output file, opened at the first snapshot
  std::vector<suite::XdmfTetStep>
      xsteps_; // the snapshots' steps of the XDMF series // the output's status attribute (core/run_summary.hpp)
};

} // namespace femdyn_app
