#include "run/progress.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace porewater {

double steps_per_second(const ChunkProgress &p)
{
  return p.chunk_seconds > 0.0 && p.chunk_steps > 0 ? p.chunk_steps / p.chunk_seconds : 0.0;
}

double seconds_left(const ChunkProgress &p)
{
  const double rate = steps_per_second(p);
  if (rate <= 0.0) return -1.0;
  const long long left = p.end_step > p.step ? p.end_step - p.step : 0;
  return left / rate;
}

std::string format_duration(double seconds)
{
  if (!(seconds >= 0.0) || seconds > 1e12) return "?";
  const long long s = std::llround(seconds);
  char text[64];
  const long long days = s / 86400, h = (s / 3600) % 24, m = (s / 60) % 60, sec = s % 60;
  if (days > 0)
    std::snprintf(text, sizeof text, "%lld d %02lld:%02lld:%02lld", days, h, m, sec);
  else
    std::snprintf(text, sizeof text, "%02lld:%02lld:%02lld", h, m, sec);
  return text;
}

std::string progress_line(const ChunkProgress &p, std::time_t now)
{
  char text[512];
  const double percent = p.end_step > 0 ? 100.0 * p.step / p.end_step : 100.0;
  int n = std::snprintf(text, sizeof text, "progress: step %lld of %lld (%.1f %%), time %.6g s",
                        p.step, p.end_step, percent, p.model_time);
  if (p.period > 0.0)
    n += std::snprintf(text + n, sizeof text - n, ", cycle %.3f", p.model_time / p.period);
  const double rate = steps_per_second(p), left = seconds_left(p);
  n += std::snprintf(text + n, sizeof text - n, "; %.0f steps/s over the last %lld steps",
                     rate, p.chunk_steps);
  std::string line(text, n > 0 ? (size_t) n : 0);
  line += "; left " + format_duration(left);
  if (left >= 0.0) {
    const std::time_t end = now + (std::time_t) std::llround(left);
    std::tm local{};
    char when[64];
    if (localtime_r(&end, &local) && std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S %Z", &local))
      line += ", done at " + std::string(when);
  }
  return line;
}

bool next_chunk_passes_limit(double elapsed, double limit, double last_chunk_seconds,
                             double safety)
{
  return limit > 0.0 && elapsed + safety * last_chunk_seconds > limit;
}

double parse_wall_time(const std::string &text)
{
  std::vector<double> fields;
  size_t start = 0;
  while (true) {
    const size_t colon = text.find(':', start);
    const std::string field = text.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
    if (field.empty()) return -1.0;
    char *end = nullptr;
    const double value = std::strtod(field.c_str(), &end);
    if (*end != '\0' || !(value >= 0.0) || !std::isfinite(value)) return -1.0;
    fields.push_back(value);
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  if (fields.size() > 3) return -1.0;
  double seconds = 0.0;
  for (double f : fields) seconds = 60.0 * seconds + f;
  return seconds;
}

}    // namespace porewater
