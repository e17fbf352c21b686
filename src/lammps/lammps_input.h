// How the LAMMPS styles read their input: the core's parsers (input/host_input.h) with an
// InputError turned into error->all, the equal-style variables a setting may name (v_name)
// through LAMMPS' Variable, and the fixes' global restart state (input/restart_state.h).
#ifndef PW_LAMMPS_INPUT_H
#define PW_LAMMPS_INPUT_H

#include "input/host_input.h"
#include "input/restart_state.h"

#include "comm.h"

#include "error.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "variable.h"

#include <cstdio>
#include <string>
#include <vector>

namespace porewater {

// LAMMPS' collective error call, for run_or_stop
struct LammpsStop {
  LAMMPS_NS::LAMMPS *lmp;
  void operator()(const std::string &message) const { lmp->error->all(FLERR, message); }
};

// run(); an InputError it throws stops the run with its message (error->all)
template <class Run> auto or_stop(LAMMPS_NS::LAMMPS *lmp, Run run) -> decltype(run())
{
  return run_or_stop(LammpsStop{lmp}, run);
}

// parse(reader) on arg[0..narg-1]; `command` names the command in messages
template <class Parse>
auto parse_or_stop(LAMMPS_NS::LAMMPS *lmp, const std::string &command, int narg, char **arg,
                   Parse parse) -> decltype(parse(std::declval<KeywordReader &>()))
{
  return parse_or_stop(LammpsStop{lmp}, command, narg, arg, parse);
}

// Fix::write_restart: rank 0 writes the state's size and block
inline void write_restart_state(LAMMPS_NS::LAMMPS *lmp, FILE *fp, const RestartFormat &format,
                                const std::vector<double> &values)
{
  if (lmp->comm->me == 0) write_restart_block(fp, format, values);
}

// Fix::restart: the values of the block (and its format version), or a stop saying how it
// differs from this command's
inline std::vector<double> read_restart_state(LAMMPS_NS::LAMMPS *lmp, const RestartFormat &format,
                                              const char *buf, long expected_count,
                                              int *version = nullptr)
{
  return or_stop(lmp, [&] { return restart_values(format, buf, expected_count, version); });
}

// LAMMPS' equal-style variables, for EqualValue
class LammpsVariables final : public VariableHost {
 public:
  explicit LammpsVariables(LAMMPS_NS::LAMMPS *lmp) : lmp_(lmp) {}
  int find(const std::string &name) override { return lmp_->input->variable->find(name.c_str()); }
  bool is_equal_style(int index) override { return lmp_->input->variable->equalstyle(index) != 0; }
  double evaluate(int index, long long next_step) override
  {
    lmp_->modify->clearstep_compute();
    const double value = lmp_->input->variable->compute_equal(index);
    lmp_->modify->addstep_compute(next_step);
    return value;
  }
  void stop(const std::string &message) override { lmp_->error->all(FLERR, message); }

 private:
  LAMMPS_NS::LAMMPS *lmp_;
};

}    // namespace porewater

#endif
