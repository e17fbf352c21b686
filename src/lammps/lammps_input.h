// How the LAMMPS styles read their input: the core's parsers (input/host_input.h) with an
// InputError turned into error->all, the equal-style variables a setting may name (v_name)
// through LAMMPS' Variable, and the fixes' global restart state (input/restart_state.h).
#ifndef PW_LAMMPS_INPUT_H
#define PW_LAMMPS_INPUT_H

#include "input/host_input.h"
#include "input/restart_state.h"

#include "comm.h"

#include "error.h"
#include "info.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "variable.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>
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
  explicit LammpsVariables(LAMMPS_NS::LAMMPS *lmp) : lmp_(lmp), read_(false) {}
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
  // The definitions as `info variables` writes them, read once (Variable keeps them private):
  // "Variable[  0]: name,  style = equal,  def = FORMULA VALUE"; rank 0 writes and reads the
  // file, every rank gets the text
  std::string formula(const std::string &name) override
  {
    if (!read_) read_definitions();
    const std::string head = "]: " + name + ",";
    size_t at = definitions_.find(head);
    if (at == std::string::npos) return "";
    const size_t def = definitions_.find("def =", at), end = definitions_.find('\n', at);
    if (def == std::string::npos || def > end) return "";
    return definitions_.substr(def + 5, end - def - 5);
  }

 private:
  void read_definitions()
  {
    read_ = true;
    std::string text;
    if (lmp_->comm->me == 0) {
      char path[] = "/tmp/porewater_variables_XXXXXX";
      const int fd = mkstemp(path);
      if (fd >= 0) {
        close(fd);
        std::vector<std::string> words = {"variables", "out", "overwrite", path};
        std::vector<char *> args;
        for (std::string &w : words) args.push_back(&w[0]);
        LAMMPS_NS::Info(lmp_).command((int) args.size(), args.data());
        if (FILE *in = std::fopen(path, "r")) {
          char buffer[4096];
          size_t n;
          while ((n = std::fread(buffer, 1, sizeof(buffer), in)) > 0) text.append(buffer, n);
          std::fclose(in);
        }
        std::remove(path);
      }
    }
    int size = (int) text.size();
    MPI_Bcast(&size, 1, MPI_INT, 0, lmp_->world);
    text.resize(size);
    if (size > 0) MPI_Bcast(&text[0], size, MPI_CHAR, 0, lmp_->world);
    definitions_ = text;
  }

  LAMMPS_NS::LAMMPS *lmp_;
  bool read_;
  std::string definitions_;
};

}    // namespace porewater

#endif
