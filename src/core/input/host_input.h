// What every host's styles do with their input, written once: run the core's parsers and
// turn an InputError into the host's error call, and evaluate the equal-style variables a
// setting may name (v_name). A host supplies only its API: a `stop` callable (its
// collective error call, which does not return) and a VariableHost.
#ifndef PW_INPUT_HOST_INPUT_H
#define PW_INPUT_HOST_INPUT_H

#include "input/formula.h"
#include "input/keywords.h"

#include <string>
#include <utility>

namespace porewater {

// run(); an InputError it throws is handed to stop(message), the host's error call
template <class Stop, class Run> auto run_or_stop(const Stop &stop, Run run) -> decltype(run())
{
  try {
    return run();
  } catch (const InputError &e) {
    stop(std::string(e.what()));
    throw;    // not reached: stop ends the run
  }
}

// parse(reader) on arg[0..narg-1]; `command` names the command in messages
template <class Stop, class Parse>
auto parse_or_stop(const Stop &stop, const std::string &command, int narg, const char *const *arg,
                   Parse parse) -> decltype(parse(std::declval<KeywordReader &>()))
{
  KeywordReader in(command, narg, arg);
  return run_or_stop(stop, [&] { return parse(in); });
}

// The host's equal-style variables.
class VariableHost {
 public:
  virtual int find(const std::string &name) = 0;    // -1: no such variable
  virtual bool is_equal_style(int index) = 0;
  // the value now; computes it references are scheduled for next_step
  virtual double evaluate(int index, long long next_step) = 0;
  // called on every rank with the same message: stop the run
  virtual void stop(const std::string &message) = 0;
  // the formula of an equal-style variable as the input gave it, the same on every rank;
  // "" where the host cannot tell
  virtual std::string formula(const std::string &name) = 0;

 protected:
  ~VariableHost() = default;
};

// A setting that is a constant or an equal-style variable of the input.
class EqualValue {
 public:
  EqualValue() = default;
  explicit EqualValue(const NumberOrVariable &v) : given_(v) {}

  // the variable must exist and be equal-style by the time the run starts; `global`: the
  // style's `variables global` (its formula must name no per-atom data)
  void resolve(VariableHost &host, const std::string &command, const char *keyword,
               bool global = false)
  {
    if (!given_.is_variable()) return;
    index_ = host.find(given_.variable);
    if (index_ < 0)
      host.stop(command + ": variable " + given_.variable + " for " + keyword + " does not exist");
    if (!host.is_equal_style(index_))
      host.stop(command + ": variable " + given_.variable + " for " + keyword +
                " is not equal-style");
    if (!global) return;
    const std::string read = atom_data_read_by(
        host.formula(given_.variable), [&host](const std::string &name) { return host.formula(name); });
    if (!read.empty())
      host.stop(command + ": variables global, but variable " + given_.variable + " for " +
                keyword + " reads per-atom data (" + read + "); give variables atoms");
  }
  bool is_variable() const { return given_.is_variable(); }
  const std::string &name() const { return given_.variable; }
  // the value now; a variable is evaluated (and its computes scheduled for next_step)
  double evaluate(VariableHost &host, long long next_step) const
  {
    return given_.is_variable() ? host.evaluate(index_, next_step) : given_.value;
  }

 private:
  NumberOrVariable given_;
  int index_ = -1;
};

}    // namespace porewater

#endif
