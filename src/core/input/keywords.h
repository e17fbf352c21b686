// The one reader of style arguments: every style of the package parses its command line
// with it, so that every bad input gets the same kind of message, naming the style, the
// keyword and what it accepts. Host-free: it throws InputError, which each host turns
// into its own error call (error->all in LAMMPS and LIGGGHTS).
#ifndef PW_INPUT_KEYWORDS_H
#define PW_INPUT_KEYWORDS_H

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

namespace porewater {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A number given in the input, or an equal-style variable `v_name` to be evaluated by the
// host when needed.
struct NumberOrVariable {
  double value = 0.0;
  std::string variable;    // empty: the constant `value`
  bool is_variable() const { return !variable.empty(); }
};

// Strict conversions: the whole token, finite, in range (no "1x", "nan", "inf", "1e999").
bool parse_number(const std::string &token, double &out);
bool parse_int(const std::string &token, int &out);

// The shortest text that reads back as v ("0.1", "-inf", "1e+300"), as LAMMPS' fmt prints
// a number, for messages that quote a value exactly.
std::string round_trip_text(double v);

class KeywordReader {
 public:
  // `command` names the command in messages, e.g. "fix darcy/pressure"; args are the tokens
  // after the style name (LAMMPS: arg + 3 for a fix)
  KeywordReader(std::string command, int narg, const char *const *arg);
  KeywordReader(std::string command, std::vector<std::string> args);

  bool done() const { return next_ >= args_.size(); }
  size_t remaining() const { return args_.size() - next_; }
  // the next token as a keyword; its values follow
  const std::string &keyword();
  // name the positional value read next, for messages (pair_coeff I J kn kt mu)
  KeywordReader &named(const char *name);
  // values of the current keyword
  // `alternative` names another accepted word in the message (`z auto`, `top noflow`)
  double number(const char *alternative = nullptr);
  double positive();
  double non_negative();
  double at_most(double high);    // a number in (0, high]
  int count();                    // an integer >= 1
  NumberOrVariable number_or_variable(const char *alternative = nullptr);
  // one of `choices`; returns its index
  int choice(std::initializer_list<const char *> choices);
  bool yes_no() { return choice({"yes", "no"}) == 0; }
  // the next token if it is `word` (consumed), for alternatives like `z auto`
  bool accept(const char *word);
  std::string word(const char *expects);    // a non-empty token (a file name, a prefix)

  [[noreturn]] void unknown_keyword(std::initializer_list<const char *> allowed) const;
  // stop unless every keyword in `names` was given (given[k] for names[k])
  void require(std::initializer_list<const char *> names, std::initializer_list<bool> given) const;
  [[noreturn]] void fail(const std::string &what) const;

  const std::string &command() const { return command_; }

 private:
  const std::string &value(const char *expects);
  [[noreturn]] void bad_value(const std::string &token, const std::string &expects) const;

  std::string command_;
  std::vector<std::string> args_;
  size_t next_ = 0;
  std::string key_;    // the keyword whose values are being read
};

}    // namespace porewater

#endif
