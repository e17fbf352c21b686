#include "input/keywords.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace porewater {

namespace {
std::string shortest(double v)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%g", v);
  return text;
}
}    // namespace

std::string round_trip_text(double v)
{
  char text[40];
  int digits = 1;
  for (; digits < 17; ++digits) {
    std::snprintf(text, sizeof(text), "%.*g", digits, v);
    if (!std::isfinite(v) || std::strtod(text, nullptr) == v) break;
  }
  // whole digits before the point rather than an exponent, up to 16 of them (10, not 1e+01)
  const int exponent = v != 0.0 && std::isfinite(v) ? (int) std::floor(std::log10(std::fabs(v))) : 0;
  if (exponent >= digits && exponent < 16) digits = exponent + 1;
  std::snprintf(text, sizeof(text), "%.*g", digits, v);
  return text;
}

bool parse_number(const std::string &token, double &out)
{
  if (token.empty()) return false;
  char *end = nullptr;
  errno = 0;
  out = std::strtod(token.c_str(), &end);
  return *end == '\0' && errno == 0 && std::isfinite(out);
}

bool parse_int(const std::string &token, int &out)
{
  if (token.empty()) return false;
  char *end = nullptr;
  errno = 0;
  const long v = std::strtol(token.c_str(), &end, 10);
  out = (int) v;
  return *end == '\0' && errno == 0 && v == out;
}

KeywordReader::KeywordReader(std::string command, int narg, const char *const *arg) :
    command_(std::move(command)), args_(arg, arg + (narg > 0 ? narg : 0))
{
}

KeywordReader::KeywordReader(std::string command, std::vector<std::string> args) :
    command_(std::move(command)), args_(std::move(args))
{
}

const std::string &KeywordReader::keyword()
{
  key_ = args_.at(next_++);
  return key_;
}

KeywordReader &KeywordReader::named(const char *name)
{
  key_ = name;
  return *this;
}

const std::string &KeywordReader::value(const char *expects)
{
  if (done()) fail(key_ + " expects " + expects + ", but the command ends there");
  return args_[next_++];
}

void KeywordReader::bad_value(const std::string &token, const std::string &expects) const
{
  fail(key_ + " expects " + expects + ", got '" + token + "'");
}

double KeywordReader::number(const char *alternative)
{
  const std::string expects = alternative ? std::string(alternative) + " or a finite number"
                                          : std::string("a finite number");
  const std::string &token = value(expects.c_str());
  double v;
  if (!parse_number(token, v)) bad_value(token, expects);
  return v;
}

double KeywordReader::positive()
{
  const std::string &token = value("a number > 0");
  double v;
  if (!parse_number(token, v) || !(v > 0.0)) bad_value(token, "a finite number > 0");
  return v;
}

double KeywordReader::non_negative()
{
  const std::string &token = value("a number >= 0");
  double v;
  if (!parse_number(token, v) || v < 0.0) bad_value(token, "a finite number >= 0");
  return v;
}

double KeywordReader::at_most(double high)
{
  const std::string expects = "a number in (0, " + shortest(high) + "]";
  const std::string &token = value(expects.c_str());
  double v;
  if (!parse_number(token, v) || !(v > 0.0 && v <= high)) bad_value(token, expects);
  return v;
}

int KeywordReader::count()
{
  const std::string &token = value("an integer >= 1");
  int v;
  if (!parse_int(token, v) || v < 1) bad_value(token, "an integer >= 1");
  return v;
}

NumberOrVariable KeywordReader::number_or_variable(const char *alternative)
{
  const std::string expects = (alternative ? std::string(alternative) + ", " : std::string()) +
      "a finite number or v_name";
  const std::string &token = value(expects.c_str());
  NumberOrVariable out;
  if (token.size() > 2 && token.compare(0, 2, "v_") == 0) {
    out.variable = token.substr(2);
    return out;
  }
  if (!parse_number(token, out.value)) bad_value(token, expects);
  return out;
}

int KeywordReader::choice(std::initializer_list<const char *> choices)
{
  std::string list;
  for (const char *c : choices) list += (list.empty() ? "" : " or ") + std::string(c);
  const std::string &token = value(list.c_str());
  int index = 0;
  for (const char *c : choices) {
    if (token == c) return index;
    ++index;
  }
  bad_value(token, list);
}

bool KeywordReader::accept(const char *word)
{
  if (done() || args_[next_] != word) return false;
  ++next_;
  return true;
}

std::string KeywordReader::word(const char *expects)
{
  const std::string &token = value(expects);
  // an empty name could not be opened later, and then on one rank only
  if (token.empty()) bad_value(token, expects);
  return token;
}

void KeywordReader::unknown_keyword(std::initializer_list<const char *> allowed) const
{
  std::string list;
  for (const char *a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
  fail("unknown keyword '" + key_ + "' (allowed: " + list + ")");
}

void KeywordReader::require(std::initializer_list<const char *> names,
                            std::initializer_list<bool> given) const
{
  std::string missing;
  auto g = given.begin();
  for (const char *n : names) {
    if (g == given.end() || !*g) missing += (missing.empty() ? "" : ", ") + std::string(n);
    if (g != given.end()) ++g;
  }
  if (!missing.empty()) fail("missing required keyword(s): " + missing);
}

void KeywordReader::fail(const std::string &what) const
{
  throw InputError("Illegal " + command_ + " command: " + what);
}

}    // namespace porewater
