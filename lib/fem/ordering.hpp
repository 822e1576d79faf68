// Fill/bandwidth reducing orderings of a symmetric graph, registry by name (one file each):
// natural, cm, rcm (own, SPARSEPAK's GENRCM of George & Liu 1981), amd (SuiteSparse), metis (METIS_NodeND),
// auto (min predicted nnz(L), the input order among the candidates).
#pragma once

#include "core/named_choice.hpp"
#include "fem/sparse.hpp"

#include <petscsys.h>

#include <string>
#include <vector>

namespace suite::fem {

using OrderingFn = std::vector<int> (*)(const Graph& g); // returns perm, perm[new] = old

std::vector<int> orderNatural(const Graph& g);
// SPARSEPAK's GENRCM (FNROOT, RCM) with (rcm) or without (cm) its reversal of each component, exactly, also
// where the input order has a smaller bandwidth or profile (choosing between them is auto's job). Neighbours of
// equal degree are taken in adjacency order: by node number for sorted lists (graphOfMatrix and nodeGraph sort
// them).
std::vector<int> orderCuthillMcKee(const Graph& g);
std::vector<int> orderReverseCuthillMcKee(const Graph& g);
std::vector<int> orderAmd(const Graph& g);
std::vector<int> orderMetis(const Graph& g);
std::vector<int> orderAuto(const Graph& g); // chooseOrdering's permutation

// auto's choice: of natural, rcm, amd and metis the one with the smallest symbolic nnz(L) (ties: that order).
struct OrderingChoice {
  std::string name; // the ordering taken
  std::vector<int> perm;
};
OrderingChoice chooseOrdering(const Graph& g);
// The ordering `name` of the registry (findOrdering checked it) with the one it took: name itself, or auto's
// choice.
OrderingChoice runOrdering(const std::string& name, const Graph& g);

// George & Liu's pseudo-peripheral node finder (SPARSEPAK FNROOT: the last candidate tried) in the component
// of root, restricted to vertices with mask[v] != 0.
int pseudoPeripheralNode(const Graph& g, int root, const std::vector<char>& mask);

std::vector<std::string> orderingNames(); // natural cm rcm amd metis auto
// The registry with each ordering's one-line help (for suite::optionsChoice: -help lists them).
std::vector<suite::Choice> orderingChoices();
// Collective error naming the known orderings on an unknown name.
PetscErrorCode findOrdering(MPI_Comm comm, const std::string& name, OrderingFn* fn);
// *perm = fn(g), run `repeat` times: the minimum thread CPU time of one run, in seconds.
double timeOrdering(OrderingFn fn, const Graph& g, int repeat, std::vector<int>* perm);

// The profile of OrderingMetrics, as the outputs describe it.
inline constexpr char kProfileDefinition[] = "sum_i (i - f_i), f_i = first nonzero column of row i of the "
                                             "permuted lower triangle (diagonal excluded)";

} // namespace suite::fem
