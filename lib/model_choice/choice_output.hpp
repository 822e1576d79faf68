// The /model_choice group of an accuracy-target run's HDF5 file, appended (by rank 0, collective call) to the
// file the final run committed:
//   attributes: families (comma list of names), target_error, target_walltime, safety, cost_model (file or
//     "pilots"), chosen_family, chosen_n, chosen_label, chosen_predicted_error, chosen_predicted_cost,
//     estimated_error, target_met, pilot_seconds (pilots and timing runs), final_seconds, total_seconds, escalations,
//     most_accurate_label, most_accurate_predicted_cost, most_accurate_predicted_error, summary;
//     per family f: config_<name> (its option values), observed_order_<name>, order_used_<name>,
//     error_constant_<name>, cost_exponent_<name>
//   candidates/{family, n, predicted_cost, predicted_error}   (family: index into families)
//   pilots/{family, n, seconds, steps, difference, estimate}  (difference: L1 distance to the previous pilot)
//   timings/{family, n, seconds, steps, ...}                  (the short timing runs of the cost model)
//   finals/{family, n, seconds, steps, difference, estimate}  (estimate: the final run's estimated error)
// cost_model.cpp reads pilots/ and timings/ back for -cost_model FILE.
#pragma once

#include "model_choice/chooser.hpp"

#include <petscsys.h>

#include <string>

namespace suite::model_choice {

PetscErrorCode writeModelChoice(MPI_Comm comm, const std::string& path, const ModelChooser& chooser);

} // namespace suite::model_choice
