// How the LIGGGHTS styles read their input: the core's parsers (input/host_input.h) with an
// InputError turned into error->all, the equal-style variables a setting may name (v_name)
// through LIGGGHTS' Variable, and the fixes' global restart state (input/restart_state.h),
// in the same block as on LAMMPS.
#ifndef PW_LIGGGHTS_INPUT_H
#define PW_LIGGGHTS_INPUT_H

#include "liggghts_compat.h"

#include "input/host_input.h"
#include "input/restart_state.h"

#include "comm.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "variable.h"

#include <cstdio>
#include <string>
#include <vector>

namespace porewater_liggghts {

// LIGGGHTS' collective error call, for porewater::run_or_stop
struct LiggghtsStop {
  LAMMPS_NS::LAMMPS *lmp;
  void operator()(const std::string &message) const { error_all(lmp, FLERR, message); }
};

// run(); an InputError it throws stops the run with its message (error->all)
template <class Run> auto or_stop(LAMMPS_NS::LAMMPS *lmp, Run run) -> decltype(run())
{
  return porewater::run_or_stop(LiggghtsStop{lmp}, run);
}

// Fix::write_restart: rank 0 holds the file and writes the state's size and block
inline void write_restart_state(LAMMPS_NS::LAMMPS *lmp, FILE *fp,
                                const porewater::RestartFormat &format,
                                const std::vector<double> &values)
{
  if (lmp->comm->me == 0) porewater::write_restart_block(fp, format, values);
}

// Fix::restart (every rank gets the block): its values (and its format version), or a stop
// saying how it differs
inline std::vector<double> read_restart_state(LAMMPS_NS::LAMMPS *lmp,
                                              const porewater::RestartFormat &format,
                                              const char *buf, long expected_count,
                                              int *version = nullptr)
{
  return or_stop(lmp, [&] { return porewater::restart_values(format, buf, expected_count, version); });
}

// LIGGGHTS' equal-style variables, for porewater::EqualValue
class LiggghtsVariables final : public porewater::VariableHost {
 public:
  explicit LiggghtsVariables(LAMMPS_NS::LAMMPS *lmp) : lmp_(lmp) {}
  int find(const std::string &name) override
  {
    std::vector<char> text(name.begin(), name.end());    // Variable::find takes a char *
    text.push_back('\0');
    return lmp_->input->variable->find(text.data());
  }
  bool is_equal_style(int index) override { return lmp_->input->variable->equalstyle(index) != 0; }
  double evaluate(int index, long long next_step) override
  {
    lmp_->modify->clearstep_compute();
    const double value = lmp_->input->variable->compute_equal(index);
    lmp_->modify->addstep_compute(next_step);
    return value;
  }
  void stop(const std::string &message) override { error_all(lmp_, FLERR, message); }
  // no /kk in LIGGGHTS: `variables global` changes nothing there, and is not checked
  std::string formula(const std::string &) override { return ""; }

 private:
  LAMMPS_NS::LAMMPS *lmp_;
};

}    // namespace porewater_liggghts

#endif
