// Writer of the /model_choice group (see choice_output.hpp).
#include "model_choice/choice_output.hpp"

#include "io/h5_append.hpp"

#include <stdexcept>

namespace suite::model_choice {

namespace {
template <typename T> void writeColumn(H5AppendFile& h5, const std::string& name, const std::vector<T>& v) {
  h5.createFixed<T>(name, v.size(), T(0));
  if (!v.empty()) h5.writeAt<T>(name, 0, v.data(), v.size());
}

void writeRuns(H5AppendFile& h5, const std::string& group, const std::vector<RunRecord>& runs) {
  std::vector<long long> fam, n, steps, failed;
  std::vector<double> sec, diff, est;
  for (const RunRecord& r : runs)
    fam.push_back(r.family), n.push_back(r.n), sec.push_back(r.seconds), diff.push_back(r.difference),
        est.push_back(r.estimate), steps.push_back(r.steps), failed.push_back(r.failed ? 1 : 0);
  writeColumn(h5, group + "/failed", failed);
  writeColumn(h5, group + "/steps", steps);
  writeColumn(h5, group + "/family", fam);
  writeColumn(h5, group + "/n", n);
  writeColumn(h5, group + "/seconds", sec);
  writeColumn(h5, group + "/difference", diff);
  writeColumn(h5, group + "/estimate", est);
}

void writeTable(H5AppendFile& h5, const ModelChooser& c) {
  std::vector<long long> fam, n;
  std::vector<double> cost, err;
  for (const CandidateRow& r : c.table())
    fam.push_back(r.family), n.push_back(r.n), cost.push_back(r.cost), err.push_back(r.error);
  writeColumn(h5, "/model_choice/candidates/family", fam);
  writeColumn(h5, "/model_choice/candidates/n", n);
  writeColumn(h5, "/model_choice/candidates/predicted_cost", cost);
  writeColumn(h5, "/model_choice/candidates/predicted_error", err);
}

void writeFamilies(H5AppendFile& h5, const ModelChooser& c) {
  const std::string g = "/model_choice";
  std::string names;
  for (size_t f = 0; f < c.families().size(); ++f) {
    const Family& fam = c.families()[f];
    names += (f ? "," : "") + fam.name;
    h5.setAttribute(g, "config_" + fam.name, optionsText(fam.options));
    h5.setAttribute(g, "observed_order_" + fam.name, c.orders()[f].p_observed);
    h5.setAttribute(g, "order_used_" + fam.name, c.orders()[f].p);
    h5.setAttribute(g, "error_constant_" + fam.name, c.orders()[f].a);
    h5.setAttribute(g, "cost_exponent_" + fam.name, c.costModel().exponent(fam.name));
    h5.setAttribute(g, "failure_" + fam.name, c.failures()[f]);
  }
  h5.setAttribute(g, "families", names);
}

void writeAttributes(H5AppendFile& h5, const ModelChooser& c) {
  const std::string g = "/model_choice";
  const ChooserSettings& s = c.settings();
  h5.setAttribute(g, "target_error", s.target_error);
  h5.setAttribute(g, "target_walltime", s.target_walltime);
  h5.setAttribute(g, "safety", s.safety);
  h5.setAttribute(g, "cost_model", c.costModel().loaded() ? c.costModel().source() : std::string("pilots"));
  h5.setAttribute(g, "chosen_family", (long long)c.chosen().family);
  h5.setAttribute(g, "chosen_n", c.chosen().n);
  h5.setAttribute(g, "chosen_label", c.label(c.chosen().family, c.chosen().n));
  h5.setAttribute(g, "chosen_predicted_error", c.chosen().error);
  h5.setAttribute(g, "chosen_predicted_cost", c.chosen().cost);
  h5.setAttribute(g, "estimated_error", c.finals().back().estimate);
  h5.setAttribute(g, "target_met", (long long)(c.met() ? 1 : 0));
  h5.setAttribute(g, "pilot_seconds", c.pilotSeconds());
  h5.setAttribute(g, "final_seconds", c.finalSeconds());
  h5.setAttribute(g, "check_seconds", c.checkSeconds());
  h5.setAttribute(g, "total_seconds", c.pilotSeconds() + c.checkSeconds() + c.finalSeconds());
  h5.setAttribute(g, "escalations", (long long)c.finals().size() - 1);
  h5.setAttribute(g, "most_accurate_label", c.label(c.mostAccurate().family, c.mostAccurate().n));
  h5.setAttribute(g, "most_accurate_predicted_cost", c.mostAccurate().cost);
  h5.setAttribute(g, "most_accurate_predicted_error", c.mostAccurate().error);
  h5.setAttribute(g, "summary", c.summary());
}
} // namespace

PetscErrorCode writeModelChoice(MPI_Comm comm, const std::string& path, const ModelChooser& chooser) {
  PetscMPIInt rank;
  char message[512] = "";
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) try {
      H5AppendFile h5;
      h5.open(path, true);
      h5.remove("/model_choice");
      writeFamilies(h5, chooser);
      writeAttributes(h5, chooser);
      writeTable(h5, chooser);
      writeRuns(h5, "/model_choice/pilots", chooser.pilots());
      writeRuns(h5, "/model_choice/finals", chooser.finals());
      writeRuns(h5, "/model_choice/timings", chooser.timings());
      writeRuns(h5, "/model_choice/checks", chooser.checks());
      h5.close();
    } catch (const std::exception& e) {
      PetscCall(PetscSNPrintf(message, sizeof message, "%s", e.what()));
    }
  PetscCallMPI(MPI_Bcast(message, sizeof message, MPI_CHAR, 0, comm));
  PetscCheck(message[0] == 0, comm, PETSC_ERR_FILE_WRITE, "writing /model_choice to %s: %s", path.c_str(),
             message);
  PetscFunctionReturn(0);
}

} // namespace suite::model_choice
