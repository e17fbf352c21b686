// The global restart state of a fix, as LAMMPS and LIGGGHTS keep it: one block of doubles
// the fix writes and reads back. The block starts with a header (a package mark, the
// style's code, its format version, the number of values that follow), so that reading a
// state written by another style, another version of the format, or a different command
// stops with a message that says what differs, instead of reading garbage.
#ifndef PW_INPUT_RESTART_STATE_H
#define PW_INPUT_RESTART_STATE_H

#include <cstdio>
#include <string>
#include <vector>

namespace porewater {

enum class RestartStyle { WallStress = 1, ShearStress = 2, Ty3 = 3, Darcy = 4 };

struct RestartFormat {
  RestartStyle style;
  int version;
  const char *command;    // for messages, e.g. "fix darcy/pressure"
  int oldest_version = 0; // > 0: the style also reads the versions from this one on
};

// the block to write: header + values
std::vector<double> restart_block(const RestartFormat &format, const std::vector<double> &values);

// Fix::write_restart on the rank that holds the file (LAMMPS and LIGGGHTS: rank 0): the
// block's size in bytes (an int), then the block
void write_restart_block(std::FILE *fp, const RestartFormat &format,
                         const std::vector<double> &values);

// the values of a block written by restart_block; an InputError unless the header matches
// `format` (its version, or one from oldest_version on) and (when expected_count >= 0)
// holds exactly expected_count values; *version, if given, receives the block's version
std::vector<double> restart_values(const RestartFormat &format, const char *block,
                                   long expected_count, int *version = nullptr);

}    // namespace porewater

#endif
