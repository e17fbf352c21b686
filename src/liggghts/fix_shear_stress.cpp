// fix shear/stress for LIGGGHTS (see doc/fix_shear_stress.rst, section LIGGGHTS).
#include "fix_shear_stress.h"

#include "liggghts_input.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace porewater_liggghts {

// fix ID group shear/stress tau T mass M
FixShearStress::FixShearStress(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  plate_.reset(new porewater::RigidPlate(or_stop(lmp, [&] {
                                           porewater::KeywordReader in("fix shear/stress", narg - 3, arg + 3);
                                           return porewater::parse_shear_stress(in);
                                         }),
                                         id));
  if (!atom->sphere_flag) error_all(lmp, FLERR, "Fix shear/stress requires atom_style sphere");
  if (domain->dimension != 3) error_all(lmp, FLERR, "Fix shear/stress requires a 3d simulation");

  vector_flag = 1;
  size_vector = porewater::RigidPlate::VECTOR_SIZE;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
}

FixShearStress::~FixShearStress() = default;

int FixShearStress::setmask()
{
  return POST_FORCE;
}

void FixShearStress::init()
{
  if (strncmp(update->integrate_style, "respa", 5) == 0)
    error_all(lmp, FLERR, "Fix shear/stress does not support run_style respa");
  // forces added after ours would break the plate's rigidity and miss ΣF_x
  const std::string warning =
      porewater::fixes_after_warning(id, porewater::fixes_after(*modify, this, POST_FORCE));
  if (!warning.empty() && comm->me == 0) error->warning(FLERR, warning.c_str());
}

porewater::PlateStep FixShearStress::now() const
{
  return porewater::PlateStep{update->ntimestep, update->dt, update->setupflag != 0};
}

void FixShearStress::setup(int /*vflag*/)
{
  plate_->setup(*this, now());
}

void FixShearStress::post_force(int /*vflag*/)
{
  plate_->post_force(*this, now());
}

/* ----------------------------------------------------------------------
   what the plate needs from LIGGGHTS
------------------------------------------------------------------------- */

porewater::SerialPlateGrains<porewater::HostGrains<tagint>> FixShearStress::plate_grains() const
{
  const porewater::ImageUnwrap unwrap{IMGMASK,      IMGMAX,       IMGBITS,     IMG2BITS,
                                      domain->h[0], domain->h[5], domain->h[4]};
  return porewater::serial_plate_grains(porewater::grains_of_atom(atom), atom->nlocal, groupbit, unwrap);
}

void FixShearStress::plate_sums(double *sums)
{
  plate_grains().plate_sums(sums);
}

void FixShearStress::momentum_sums(double *sums)
{
  plate_grains().momentum_sums(sums);
}

void FixShearStress::move_as_plate(double force_per_mass)
{
  plate_grains().move_as_plate(force_per_mass);
}

void FixShearStress::set_velocity_x(double velocity)
{
  plate_grains().set_velocity_x(velocity);
}

void FixShearStress::sum_over_ranks(double *values, int n)
{
  MPI_Allreduce(MPI_IN_PLACE, values, n, MPI_DOUBLE, MPI_SUM, world);
}

double FixShearStress::area()
{
  return domain->xprd * domain->yprd;
}

double FixShearStress::force_to_velocity()
{
  return force->ftm2v;
}

double FixShearStress::neighbor_skin()
{
  return neighbor->skin;
}

std::string FixShearStress::group_name() const
{
  return group->names[igroup];
}

void FixShearStress::stop(const std::string &message)
{
  error_all(lmp, FLERR, message);
}

/* ----------------------------------------------------------------------
   outputs and restart
------------------------------------------------------------------------- */

double FixShearStress::compute_vector(int n)
{
  return plate_->vector(*this, n);
}

void FixShearStress::write_restart(FILE *fp)
{
  write_restart_state(lmp, fp, porewater::RigidPlate::RESTART, plate_->restart_state());
}

void FixShearStress::restart(char *buf)
{
  plate_->restore(read_restart_state(lmp, porewater::RigidPlate::RESTART, buf, 1));
}

}    // namespace porewater_liggghts
