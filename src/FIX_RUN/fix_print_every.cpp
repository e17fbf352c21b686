/* ----------------------------------------------------------------------
   fix print/every (see doc/fix_print_every.rst)

   The line is LAMMPS' fix print's: the text with its $ variables substituted by
   Input::substitute, written as it comes out; only when it is written differs.
------------------------------------------------------------------------- */

#include "fix_print_every.h"

#include "input/settings.h"
#include "lammps_input.h"

#include "comm.h"
#include "error.h"
#include "input.h"
#include "memory.h"
#include "modify.h"
#include "update.h"
#include "utils.h"

#include <cerrno>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ----------------------------------------------------------------------
   fix ID group print/every N "text" [file F | append F] [screen yes|no] [title T]
------------------------------------------------------------------------- */

FixPrintEvery::FixPrintEvery(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), screen(true), fp(nullptr), text(nullptr), copy(nullptr), work(nullptr)
{
  const porewater::PrintEverySettings settings = porewater::parse_or_stop(
      lmp, "fix print/every", narg - 3, arg + 3, porewater::parse_print_every);
  nevery = settings.every;    // LAMMPS calls end_of_step on the multiples of N only
  // with KOKKOS the atom data come to the host for the line's variables, and go back to the
  // device only if changed: the line changes none
  datamask_modify = 0;
  screen = settings.screen;
  // the file first: an error stops the constructor before it allocates what only the
  // destructor frees
  if (!settings.file.empty() && comm->me == 0) {
    fp = fopen(settings.file.c_str(), settings.append ? "a" : "w");
    if (!fp)
      error->one(FLERR, "fix print/every: cannot open file {}: {}", settings.file,
                 std::strerror(errno));
    if (settings.title_given)
      fprintf(fp, "%s\n", settings.title.c_str());
    else
      fprintf(fp, "# Fix print/every output for fix %s\n", id);
  }
  text = utils::strdup(settings.text);
  maxcopy = maxwork = (int) settings.text.size() + 1;
  copy = (char *) memory->smalloc(maxcopy, "fix/print/every:copy");
  work = (char *) memory->smalloc(maxwork, "fix/print/every:work");
}

FixPrintEvery::~FixPrintEvery()
{
  delete[] text;
  memory->sfree(copy);
  memory->sfree(work);
  if (fp) fclose(fp);
}

int FixPrintEvery::setmask()
{
  return END_OF_STEP;
}

bigint FixPrintEvery::next_line() const
{
  return (update->ntimestep / nevery) * nevery + nevery;
}

// computes that keep their invocation steps learn when the line's variables may call them
void FixPrintEvery::init()
{
  modify->addstep_compute_all(next_line());
}

void FixPrintEvery::end_of_step()
{
  if (update->ntimestep % nevery) return;
  modify->clearstep_compute();
  strcpy(copy, text);
  input->substitute(copy, work, maxcopy, maxwork, 0);
  modify->addstep_compute(next_line());
  if (comm->me != 0) return;
  if (screen) utils::logmesg(lmp, std::string(copy) + "\n");
  if (fp) {
    fprintf(fp, "%s\n", copy);
    fflush(fp);
  }
}
