#include "input/restart_state.h"

#include "input/keywords.h"

#include <cmath>
#include <cstring>

namespace porewater {

namespace {
const double PACKAGE_MARK = 7.0e15 + 7203.0;    // "pw" in an exact double no state starts with
const int HEADER = 4;                           // mark, style, version, count
}    // namespace

std::vector<double> restart_block(const RestartFormat &format, const std::vector<double> &values)
{
  std::vector<double> block = {PACKAGE_MARK, double(int(format.style)), double(format.version),
                               double(values.size())};
  block.insert(block.end(), values.begin(), values.end());
  return block;
}

void write_restart_block(std::FILE *fp, const RestartFormat &format,
                         const std::vector<double> &values)
{
  const std::vector<double> block = restart_block(format, values);
  const int size = (int) (block.size() * sizeof(double));
  std::fwrite(&size, sizeof(int), 1, fp);
  std::fwrite(block.data(), sizeof(double), block.size(), fp);
}

std::vector<double> restart_values(const RestartFormat &format, const char *block,
                                   long expected_count, int *version)
{
  double header[HEADER];
  std::memcpy(header, block, sizeof(header));
  const std::string what = "the restart file's state for " + std::string(format.command);
  if (header[0] != PACKAGE_MARK || header[1] != double(int(format.style)))
    throw InputError(what + " was not written by this style of this package");
  const int oldest = format.oldest_version > 0 ? format.oldest_version : format.version;
  if (!(header[2] == std::floor(header[2]) && header[2] >= oldest && header[2] <= format.version))
    throw InputError(what + " has format version " + std::to_string((long) header[2]) +
                     ", this build reads version " +
                     (oldest < format.version ? std::to_string(oldest) + " to " : std::string()) +
                     std::to_string(format.version));
  if (version) *version = (int) header[2];
  const double count = header[3];
  if (!(count >= 0.0 && count == std::floor(count) && count < 1e12))
    throw InputError(what + " is damaged: its value count is " + std::to_string(count));
  if (expected_count >= 0 && count != double(expected_count))
    throw InputError(what + " holds " + std::to_string((long) count) + " values where this command "
                     "needs " + std::to_string(expected_count));
  std::vector<double> values((size_t) count);
  std::memcpy(values.data(), block + sizeof(header), values.size() * sizeof(double));
  return values;
}

}    // namespace porewater
