/* ----------------------------------------------------------------------
   fix progress (see doc/fix_progress.rst)

   Rank 0 reads the wall clock and decides; the decision and the numbers are broadcast, so
   that every rank takes the same branch of an input's `if`.
------------------------------------------------------------------------- */

#include "fix_progress.h"

#include "lammps_compat.h"
#include "lammps_input.h"
#include "run/progress.h"

#include "comm.h"
#include "error.h"
#include "timer.h"
#include "update.h"
#include "utils.h"

#include <ctime>

using namespace LAMMPS_NS;

FixProgress::FixProgress(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), started(MPI_Wtime()), chunk_began(0.0), timing(false),
    chunk_first_step(0), values{0.0, 0.0, -1.0, 0.0}
{
  settings = porewater::parse_or_stop(lmp, "fix progress", narg - 3, arg + 3,
                                      [](porewater::KeywordReader &in) { return porewater::parse_progress(in); });
#if !PW_LAMMPS_RESTART_HAS_TIME
  if (update->ntimestep > 0 && comm->me == 0)
    error->warning(FLERR, "fix progress: this LAMMPS keeps no simulated time in restart files "
                   "(before 3 May 2022): a run continued from one starts its time at 0 "
                   "(scripts/patches/lammps-restart-time.patch adds it)");
#endif
  vector_flag = 1;
  size_vector = 4;
  global_freq = 1;
  extvector = 0;
}

int FixProgress::setmask()
{
  return 0;
}

// the first chunk is timed from its setup; later ones from the previous chunk's end, so that
// what the input does between runs (the checkpoint) counts in the chunk that follows it
void FixProgress::setup(int /*vflag*/)
{
  if (!timing) {
    chunk_began = MPI_Wtime();
    timing = true;
  }
  chunk_first_step = update->ntimestep;
}

void FixProgress::post_run()
{
  const double now = MPI_Wtime();
  porewater::ChunkProgress p{};
  p.step = update->ntimestep;
  p.end_step = settings.end_step;
  p.model_time = porewater::simulated_time(update, update->ntimestep);
  p.period = settings.period;
  p.chunk_steps = update->ntimestep - chunk_first_step;
  p.chunk_seconds = now - chunk_began;
  chunk_began = now;
  if (comm->me == 0) {
    const double elapsed = now - started;
    const bool finished = p.step >= p.end_step;
    const bool stop = !finished &&
        porewater::next_chunk_passes_limit(elapsed, settings.walltime, p.chunk_seconds,
                                           settings.safety);
    values[0] = stop ? 1.0 : 0.0;
    values[1] = porewater::steps_per_second(p);
    values[2] = porewater::seconds_left(p);
    values[3] = elapsed;
    std::string line = porewater::progress_line(p, std::time(nullptr)) + "\n";
    if (stop)
      line += "progress: stopping at step " + std::to_string(p.step) + ": the next chunk (~" +
          porewater::format_duration(settings.safety * p.chunk_seconds) + ") would end past the " +
          "walltime " + porewater::format_duration(settings.walltime) + " (" +
          porewater::format_duration(elapsed) + " used)\n";
    utils::logmesg(lmp, line);
  }
  MPI_Bcast(values, 4, MPI_DOUBLE, 0, world);
  // a `run N every M` stops after this chunk's commands; later run commands do nothing
  if (values[0] > 0.0) timer->force_timeout();
}

double FixProgress::compute_vector(int n)
{
  return n >= 0 && n < 4 ? values[n] : 0.0;
}
