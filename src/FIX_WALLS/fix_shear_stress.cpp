/* ----------------------------------------------------------------------
   fix shear/stress (see doc/fix_shear_stress.rst)

   In post_force, after the pair style and the fixes defined before it have added their
   forces, the plate (walls/rigid_plate.h) replaces each grain's f_x by m_i·a_plate; the
   integrator then moves every grain with the same x-acceleration, so the layer stays
   rigid under nve/sphere as under nve/sphere/ty3.
------------------------------------------------------------------------- */

#include "fix_shear_stress.h"

#include "grains/host_grains.h"
#include "lammps_compat.h"
#include "lammps_input.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

/* ----------------------------------------------------------------------
   fix ID group shear/stress tau T mass M
------------------------------------------------------------------------- */

FixShearStress::FixShearStress(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  plate.reset(new porewater::RigidPlate(
      porewater::parse_or_stop(lmp, "fix shear/stress", narg - 3, arg + 3, porewater::parse_shear_stress),
      id));
  if (!porewater::has_sphere_attributes(atom)) error->all(FLERR, "Fix shear/stress requires atom_style sphere");
  if (domain->dimension != 3) error->all(FLERR, "Fix shear/stress requires a 3d simulation");

  vector_flag = 1;
  size_vector = porewater::RigidPlate::VECTOR_SIZE;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
}

FixShearStress::~FixShearStress() = default;

int FixShearStress::setmask()
{
  return PRE_NEIGHBOR | POST_FORCE;
}

void FixShearStress::init()
{
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Fix shear/stress does not support run_style respa");
  // forces added after ours would break the plate's rigidity and miss ΣF_x
  const std::string warning =
      porewater::fixes_after_warning(id, porewater::fixes_after(*modify, this, POST_FORCE));
  if (!warning.empty() && comm->me == 0) error->warning(FLERR, warning);
}

porewater::PlateStep FixShearStress::now() const
{
  return porewater::PlateStep{update->ntimestep, update->dt, update->setupflag != 0};
}

void FixShearStress::setup(int /*vflag*/)
{
  list_members();    // a run may start with grains moved, added, sorted or regrouped
  plate->setup(*this, now());
}

// after LAMMPS has exchanged and sorted the grains, before the step's forces
void FixShearStress::pre_neighbor()
{
  list_members();
}

void FixShearStress::list_members()
{
  const int *mask = atom->mask;
  members.rebuild(atom->nlocal, [&](int i) { return (mask[i] & groupbit) != 0; });
}

void FixShearStress::post_force(int /*vflag*/)
{
  plate->post_force(*this, now());
}

/* ----------------------------------------------------------------------
   what the plate needs from LAMMPS
------------------------------------------------------------------------- */

porewater::ImageUnwrap FixShearStress::image_unwrap() const
{
  return porewater::ImageUnwrap{IMGMASK,      IMGMAX,       IMGBITS,     IMG2BITS,
                                domain->h[0], domain->h[5], domain->h[4]};
}

porewater::SerialPlateGrains<porewater::HostGrains<imageint>> FixShearStress::plate_grains() const
{
  // between runs (an output of the vector) grains may have changed since the list
  return porewater::serial_plate_grains(porewater::grains_of_atom(atom), atom->nlocal, groupbit,
                                        image_unwrap(), update->whichflag ? &members : nullptr);
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
  error->all(FLERR, message);
}

/* ----------------------------------------------------------------------
   outputs and restart
------------------------------------------------------------------------- */

double FixShearStress::compute_vector(int n)
{
  return plate->vector(*this, n);
}

void FixShearStress::write_restart(FILE *fp)
{
  porewater::write_restart_state(lmp, fp, porewater::RigidPlate::RESTART, plate->restart_state());
}

void FixShearStress::restart(char *buf)
{
  plate->restore(porewater::read_restart_state(lmp, porewater::RigidPlate::RESTART, buf, 1));
}
