// The progress of a long run made of chunks (one `run` each, a checkpoint after each): the
// rate over the last chunk, the wall time left and the finish time, and whether the next
// chunk still ends before a wall-time limit. Host-free: the fix progress of each host
// measures the wall clock and prints what this composes.
#ifndef PW_RUN_PROGRESS_H
#define PW_RUN_PROGRESS_H

#include <ctime>
#include <string>

namespace porewater {

// Where the run stands at the end of a chunk.
struct ChunkProgress {
  long long step;              // the step reached
  long long end_step;          // the last step of the whole run
  double model_time;           // simulated time reached
  double period;               // the forcing period (> 0: the cycle reached is reported)
  long long chunk_steps;       // steps of the chunk just ended
  double chunk_seconds;        // its wall time, the previous chunk's checkpoint included
};

// Steps per second over the last chunk; 0 when nothing was timed.
double steps_per_second(const ChunkProgress &p);

// Wall seconds to the end of the run at the last chunk's rate; negative when unknown.
double seconds_left(const ChunkProgress &p);

// "3 d 04:05:06", "04:05:06", or "?" for a negative (unknown) duration.
std::string format_duration(double seconds);

// One line: step, percent, model time and cycle, rate, time left and the local finish time
// (`now`: the wall clock when the chunk ended).
std::string progress_line(const ChunkProgress &p, std::time_t now);

// Whether the next chunk, estimated as `safety` times the last one, would end past the
// wall-time limit: `elapsed` seconds of the job so far, `limit` its limit (<= 0: none).
bool next_chunk_passes_limit(double elapsed, double limit, double last_chunk_seconds,
                             double safety);

// "HH:MM:SS", "MM:SS" or seconds as a number (what a batch queue's limit looks like), in
// seconds; negative for anything else.
double parse_wall_time(const std::string &text);

}    // namespace porewater

#endif
