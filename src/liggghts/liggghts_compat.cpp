#include "liggghts_compat.h"

#include "comm.h"
#include "error.h"

#include <cstdio>
#include <cstdlib>

using namespace LAMMPS_NS;

namespace porewater_liggghts {

void error_all(LAMMPS *lmp, const char *file, int line, const std::string &message)
{
  lmp->error->all(file, line, message.c_str());
  std::abort();    // Error::all ends the program (MPI_Finalize, exit)
}

void error_one(LAMMPS *lmp, const char *file, int line, const std::string &message)
{
  lmp->error->one(file, line, message.c_str());
  std::abort();    // Error::one ends the program (MPI_Abort)
}

void print_all(LAMMPS *lmp, const std::string &text)
{
  if (lmp->comm->me != 0) return;
  if (lmp->screen) fprintf(lmp->screen, "%s\n", text.c_str());
  if (lmp->logfile) fprintf(lmp->logfile, "%s\n", text.c_str());
}

}    // namespace porewater_liggghts
