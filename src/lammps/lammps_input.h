// How the LAMMPS styles read their input: the core's KeywordReader and settings parsers on
// a command's arguments, an InputError turned into error->all; the equal-style variables a
// setting may name (v_name), resolved in init() and evaluated on the steps that need them;
// and the fixes' global restart state (input/restart_state.h).
#ifndef PW_LAMMPS_INPUT_H
#define PW_LAMMPS_INPUT_H

#include "input/keywords.h"
#include "input/restart_state.h"

#include "comm.h"

#include "error.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "variable.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace porewater {

// run(); an InputError it throws stops the run with its message (error->all)
template <class Run> auto or_stop(LAMMPS_NS::LAMMPS *lmp, Run run) -> decltype(run())
{
  try {
    return run();
  } catch (const InputError &e) {
    lmp->error->all(FLERR, std::string(e.what()));
  }
}

// parse(reader) on arg[0..narg-1]; `command` names the command in messages
template <class Parse>
auto parse_or_stop(LAMMPS_NS::LAMMPS *lmp, const std::string &command, int narg, char **arg,
                   Parse parse) -> decltype(parse(std::declval<KeywordReader &>()))
{
  KeywordReader in(command, narg, arg);
  return or_stop(lmp, [&] { return parse(in); });
}

// Fix::write_restart: rank 0 writes the state's size and block
inline void write_restart_state(LAMMPS_NS::LAMMPS *lmp, FILE *fp, const RestartFormat &format,
                                const std::vector<double> &values)
{
  if (lmp->comm->me != 0) return;
  const std::vector<double> block = restart_block(format, values);
  const int size = (int) (block.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(block.data(), sizeof(double), block.size(), fp);
}

// Fix::restart: the values of the block, or a stop saying how it differs from this command's
inline std::vector<double> read_restart_state(LAMMPS_NS::LAMMPS *lmp, const RestartFormat &format,
                                              const char *buf, long expected_count)
{
  return or_stop(lmp, [&] { return restart_values(format, buf, expected_count); });
}

// A setting that is a constant or an equal-style variable of the input.
class EqualValue {
 public:
  EqualValue() = default;
  explicit EqualValue(const NumberOrVariable &v) : given(v) {}

  // the variable must exist and be equal-style by the time the run starts
  void resolve(LAMMPS_NS::LAMMPS *lmp, const std::string &command, const char *keyword)
  {
    if (!given.is_variable()) return;
    index = lmp->input->variable->find(given.variable.c_str());
    if (index < 0)
      lmp->error->all(FLERR, "{}: variable {} for {} does not exist", command, given.variable,
                      keyword);
    if (!lmp->input->variable->equalstyle(index))
      lmp->error->all(FLERR, "{}: variable {} for {} is not equal-style", command,
                      given.variable, keyword);
  }
  bool is_variable() const { return given.is_variable(); }
  const std::string &name() const { return given.variable; }
  // the value now; a variable is evaluated (and its computes scheduled for next_step)
  double evaluate(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::bigint next_step) const
  {
    if (!given.is_variable()) return given.value;
    lmp->modify->clearstep_compute();
    const double value = lmp->input->variable->compute_equal(index);
    lmp->modify->addstep_compute(next_step);
    return value;
  }

 private:
  NumberOrVariable given;
  int index = -1;
};

}    // namespace porewater

#endif
