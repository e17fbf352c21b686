/* ----------------------------------------------------------------------
   pair_style linear/coulomb (see doc/pair_linear_coulomb.rst)
------------------------------------------------------------------------- */

#include "pair_linear_coulomb.h"

#include "linear_coulomb_contact.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using porewater::ContactForce;

/* ---------------------------------------------------------------------- */

PairLinearCoulomb::PairLinearCoulomb(LAMMPS *lmp) :
    PairGranHookeHistory(lmp), lever(porewater::LEVER_CONTACT), track_dissipation(0),
    dissipated(0.0), uniform_coeffs(-1), overlap_limit(0.5), kn_ij(nullptr), kt_ij(nullptr), mu_ij(nullptr)
{
  // the base class' global coefficients: no damping anywhere
  kn = kt = gamman = gammat = xmu = 0.0;
  dampflag = 0;
  limit_damping = 0;
  single_extra = 4;    // f_t (x, y, z) and |f_t|
  delete[] svector;
  svector = new double[single_extra];
  nextra = 1;    // compute pair: [1] = cumulative frictional dissipation
  pvector = new double[nextra];
  pvector[0] = 0.0;
}

PairLinearCoulomb::~PairLinearCoulomb()
{
  if (copymode) return;
  memory->destroy(kn_ij);
  memory->destroy(kt_ij);
  memory->destroy(mu_ij);
  delete[] pvector;
}

/* ---------------------------------------------------------------------- */

void PairLinearCoulomb::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (uniform_coeffs < 0) uniform_coeffs = coefficients_are_uniform() ? 1 : 0;
  // one set of coefficients for every type pair (the common case) needs no type lookups,
  // and then whether pairs have friction is known before the loop
  if (!uniform_coeffs)
    eval<MIXED>();
  else if (porewater::is_frictionless(kt_ij[1][1], mu_ij[1][1]))
    eval<UNIFORM_FRICTIONLESS>();
  else
    eval<UNIFORM_FRICTIONAL>();
  pvector[0] = dissipated;
}

void PairLinearCoulomb::broken_contact(int i, int j, double overlap)
{
  double **x = atom->x;
  error->one(FLERR,
             "Pair linear/coulomb: at step {} grains {} and {} at ({:.6g} {:.6g} {:.6g}) and "
             "({:.6g} {:.6g} {:.6g}) overlap by {:.6g}, more than overlap_limit {} of the smaller "
             "radius (or not finite): the time step is too large for kn, or the run has blown up",
             update->ntimestep, atom->tag[i], atom->tag[j], x[i][0], x[i][1], x[i][2], x[j][0],
             x[j][1], x[j][2], overlap, overlap_limit);
}

bool PairLinearCoulomb::coefficients_are_uniform() const
{
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = 1; j <= atom->ntypes; j++)
      if (kn_ij[i][j] != kn_ij[1][1] || kt_ij[i][j] != kt_ij[1][1] || mu_ij[i][j] != mu_ij[1][1])
        return false;
  return true;
}

template <int MODE> void PairLinearCoulomb::eval()
{
  constexpr bool UNIFORM = MODE != MIXED;
  const int update_history = update->setupflag ? 0 : 1;

  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  double **omega = atom->omega;
  double **torque = atom->torque;
  const double *radius = atom->radius;
  const int *type = atom->type;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;

  const int inum = list->inum;
  const int *ilist = list->ilist;
  const int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  int **firsttouch = fix_history->firstflag;
  double **firstxi = fix_history->firstvalue;
  // locals, not members: stores into f and torque could alias a member double
  const int lever_mode = lever, tracking = track_dissipation;
  const double limit = overlap_limit;
  const double step = dt;
  double lost = 0.0;

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const double xtmp = x[i][0], ytmp = x[i][1], ztmp = x[i][2];
    const double radi = radius[i];
    const int itype = UNIFORM ? 1 : type[i];
    const double *kn_row = kn_ij[itype], *kt_row = kt_ij[itype], *mu_row = mu_ij[itype];
    const int *jlist = firstneigh[i];
    const int jnum = numneigh[i];
    int *touch = firsttouch[i];
    double *allxi = firstxi[i];

    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double delx = xtmp - x[j][0];
      const double dely = ytmp - x[j][1];
      const double delz = ztmp - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const double radj = radius[j];
      const double radsum = radi + radj;
      double *xi = &allxi[3 * jj];

      if (rsq >= radsum * radsum) {    // an open contact forgets its history
        if (tracking && touch[jj])
          lost += porewater::pair_share(j, nlocal, newton_pair) *
              porewater::opening_loss(kt_row[UNIFORM ? 1 : type[j]], xi);
        if (touch[jj]) {    // most stay apart: no stores (flag 0 means history 0)
          touch[jj] = 0;
          xi[0] = xi[1] = xi[2] = 0.0;
        }
        continue;
      }
      touch[jj] = 1;
      const int jtype = UNIFORM ? 1 : type[j];
      const double kt_pair = kt_row[jtype], mu_pair = mu_row[jtype];
      // a frictionless pair has no torque and no spring
      const bool frictional =
          UNIFORM ? MODE == UNIFORM_FRICTIONAL : !porewater::is_frictionless(kt_pair, mu_pair);
      const ContactForce c = porewater::linear_coulomb_contact(
          delx, dely, delz, rsq, radi, radj, v[i], v[j], omega[i], omega[j], kn_row[jtype],
          kt_pair, mu_pair, lever_mode, update_history, step, xi, frictional);
      if (porewater::contact_is_broken(c.overlap, radi, radj, limit))
        broken_contact(i, j, c.overlap);
      if (tracking)
        lost += porewater::pair_share(j, nlocal, newton_pair) * porewater::spring_loss(kt_pair, c, xi);

      f[i][0] += c.f[0];
      f[i][1] += c.f[1];
      f[i][2] += c.f[2];
      if (frictional) {
        torque[i][0] -= c.lever_i * c.tor[0];
        torque[i][1] -= c.lever_i * c.tor[1];
        torque[i][2] -= c.lever_i * c.tor[2];
      }
      if (newton_pair || j < nlocal) {
        f[j][0] -= c.f[0];
        f[j][1] -= c.f[1];
        f[j][2] -= c.f[2];
        if (frictional) {
          torque[j][0] -= c.lever_j * c.tor[0];
          torque[j][1] -= c.lever_j * c.tor[1];
          torque[j][2] -= c.lever_j * c.tor[2];
        }
      }
      if (evflag)
        ev_tally_xyz(i, j, nlocal, newton_pair,
                     eflag_either ? porewater::contact_energy(kn_row[jtype], kt_pair, c, xi) : 0.0,
                     0.0, c.f[0], c.f[1], c.f[2], delx, dely, delz);
    }
  }
  dissipated += lost;
}

/* ----------------------------------------------------------------------
   pair_style linear/coulomb [lever contact|radius] [dissipation yes|no]
------------------------------------------------------------------------- */

void PairLinearCoulomb::settings(int narg, char **arg)
{
  lever = porewater::LEVER_CONTACT;
  track_dissipation = 0;
  overlap_limit = 0.5;
  int iarg = 0;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "lever") == 0) {
      if (iarg + 2 > narg) error->all(FLERR, "Illegal pair_style linear/coulomb: lever needs a value (contact or radius)");
      if (strcmp(arg[iarg + 1], "contact") == 0)
        lever = porewater::LEVER_CONTACT;
      else if (strcmp(arg[iarg + 1], "radius") == 0)
        lever = porewater::LEVER_RADIUS;
      else
        error->all(FLERR, "Illegal pair_style linear/coulomb: lever must be contact or radius, not {}",
                   arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "dissipation") == 0) {
      if (iarg + 2 > narg) error->all(FLERR, "Illegal pair_style linear/coulomb: dissipation needs yes or no");
      if (strcmp(arg[iarg + 1], "yes") == 0)
        track_dissipation = 1;
      else if (strcmp(arg[iarg + 1], "no") == 0)
        track_dissipation = 0;
      else
        error->all(FLERR, "Illegal pair_style linear/coulomb: dissipation must be yes or no, not {}",
                   arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "overlap_limit") == 0) {
      if (iarg + 2 > narg) error->all(FLERR, "Illegal pair_style linear/coulomb: overlap_limit needs a value");
      overlap_limit = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (overlap_limit <= 0.0 || overlap_limit > 2.0)
        error->all(FLERR, "Illegal pair_style linear/coulomb: overlap_limit must be in (0, 2], not {}",
                   overlap_limit);
      iarg += 2;
    } else {
      error->all(FLERR,
                 "Illegal pair_style linear/coulomb keyword: {} (allowed: lever, dissipation, "
                 "overlap_limit)",
                 arg[iarg]);
    }
  }
}

/* ---------------------------------------------------------------------- */

void PairLinearCoulomb::allocate_coeffs()
{
  if (!allocated) allocate();
  if (kn_ij) return;
  const int n = atom->ntypes;
  memory->create(kn_ij, n + 1, n + 1, "pair:kn");
  memory->create(kt_ij, n + 1, n + 1, "pair:kt");
  memory->create(mu_ij, n + 1, n + 1, "pair:mu");
  for (int i = 0; i <= n; i++)
    for (int j = 0; j <= n; j++) kn_ij[i][j] = kt_ij[i][j] = mu_ij[i][j] = 0.0;
}

/* ----------------------------------------------------------------------
   pair_coeff I J kn kt mu
------------------------------------------------------------------------- */

void PairLinearCoulomb::coeff(int narg, char **arg)
{
  if (narg != 5)
    error->all(FLERR, "Incorrect args for pair_coeff linear/coulomb: expected I J kn kt mu, got {} args",
               narg);
  allocate_coeffs();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  const double kn_one = utils::numeric(FLERR, arg[2], false, lmp);
  const double kt_one = utils::numeric(FLERR, arg[3], false, lmp);
  const double mu_one = utils::numeric(FLERR, arg[4], false, lmp);
  if (kn_one <= 0.0) error->all(FLERR, "pair_coeff linear/coulomb: kn must be > 0, got {}", kn_one);
  if (kt_one < 0.0) error->all(FLERR, "pair_coeff linear/coulomb: kt must be >= 0, got {}", kt_one);
  if (mu_one < 0.0) error->all(FLERR, "pair_coeff linear/coulomb: mu must be >= 0, got {}", mu_one);

  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      kn_ij[i][j] = kn_one;
      kt_ij[i][j] = kt_one;
      mu_ij[i][j] = mu_one;
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0) error->all(FLERR, "Incorrect args for pair_coeff linear/coulomb: no type pair matched");
}

/* ---------------------------------------------------------------------- */

void PairLinearCoulomb::init_style()
{
  if (!atom->sphere_flag)
    error->all(FLERR, "Pair linear/coulomb requires atom_style sphere (radius, rmass, omega, torque)");
  PairGranHookeHistory::init_style();
  uniform_coeffs = -1;    // decided at the first compute(), after init_one() mixed them
}

/* ----------------------------------------------------------------------
   mixing for I != J without explicit pair_coeff: geometric mean of kn, kt, mu
------------------------------------------------------------------------- */

double PairLinearCoulomb::init_one(int i, int j)
{
  allocate_coeffs();
  if (setflag[i][j] == 0) {
    if (setflag[i][i] == 0 || setflag[j][j] == 0)
      error->all(FLERR, "Pair linear/coulomb: coefficients for types {} {} are not set and cannot be mixed",
                 i, j);
    kn_ij[i][j] = porewater::mix_geometric(kn_ij[i][i], kn_ij[j][j]);
    kt_ij[i][j] = porewater::mix_geometric(kt_ij[i][i], kt_ij[j][j]);
    mu_ij[i][j] = porewater::mix_geometric(mu_ij[i][i], mu_ij[j][j]);
  }
  kn_ij[j][i] = kn_ij[i][j];
  kt_ij[j][i] = kt_ij[i][j];
  mu_ij[j][i] = mu_ij[i][j];
  return PairGranHookeHistory::init_one(i, j);
}

/* ---------------------------------------------------------------------- */

void PairLinearCoulomb::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (setflag[i][j]) {
        fwrite(&kn_ij[i][j], sizeof(double), 1, fp);
        fwrite(&kt_ij[i][j], sizeof(double), 1, fp);
        fwrite(&mu_ij[i][j], sizeof(double), 1, fp);
      }
    }
}

void PairLinearCoulomb::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate_coeffs();
  const int me = comm->me;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (setflag[i][j]) {
        if (me == 0) {
          utils::sfread(FLERR, &kn_ij[i][j], sizeof(double), 1, fp, nullptr, error);
          utils::sfread(FLERR, &kt_ij[i][j], sizeof(double), 1, fp, nullptr, error);
          utils::sfread(FLERR, &mu_ij[i][j], sizeof(double), 1, fp, nullptr, error);
        }
        MPI_Bcast(&kn_ij[i][j], 1, MPI_DOUBLE, 0, world);
        MPI_Bcast(&kt_ij[i][j], 1, MPI_DOUBLE, 0, world);
        MPI_Bcast(&mu_ij[i][j], 1, MPI_DOUBLE, 0, world);
      }
    }
}

void PairLinearCoulomb::write_restart_settings(FILE *fp)
{
  fwrite(&lever, sizeof(int), 1, fp);
  fwrite(&track_dissipation, sizeof(int), 1, fp);
  fwrite(&overlap_limit, sizeof(double), 1, fp);
}

void PairLinearCoulomb::read_restart_settings(FILE *fp)
{
  if (comm->me == 0) {
    utils::sfread(FLERR, &lever, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &track_dissipation, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &overlap_limit, sizeof(double), 1, fp, nullptr, error);
  }
  MPI_Bcast(&lever, 1, MPI_INT, 0, world);
  MPI_Bcast(&track_dissipation, 1, MPI_INT, 0, world);
  MPI_Bcast(&overlap_limit, 1, MPI_DOUBLE, 0, world);
}

void PairLinearCoulomb::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    fprintf(fp, "%d %g %g %g\n", i, kn_ij[i][i], kt_ij[i][i], mu_ij[i][i]);
}

void PairLinearCoulomb::write_data_all(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      fprintf(fp, "%d %d %g %g %g\n", i, j, kn_ij[i][j], kt_ij[i][j], mu_ij[i][j]);
}

/* ----------------------------------------------------------------------
   for compute pair/local: returns the contact energy, fforce = normal force / r;
   svector = tangential force (x, y, z) and its magnitude. History is not modified.
------------------------------------------------------------------------- */

double PairLinearCoulomb::single(int i, int j, int itype, int jtype, double rsq, double, double,
                                 double &fforce)
{
  const double radi = atom->radius[i], radj = atom->radius[j];
  const double radsum = radi + radj;
  if (rsq >= radsum * radsum) {
    fforce = 0.0;
    for (int m = 0; m < single_extra; m++) svector[m] = 0.0;
    return 0.0;
  }

  // find the stored history of this pair (same search as gran/hooke/history)
  const int jnum = list->numneigh[i];
  const int *jlist = list->firstneigh[i];
  for (int jj = 0; jj < jnum; jj++) {
    neighprev++;
    if (neighprev >= jnum) neighprev = 0;
    if ((jlist[neighprev] & NEIGHMASK) == j) break;
  }
  const double *stored = &fix_history->firstvalue[i][3 * neighprev];
  double xi[3] = {stored[0], stored[1], stored[2]};

  double **x = atom->x;
  const double delx = x[i][0] - x[j][0], dely = x[i][1] - x[j][1], delz = x[i][2] - x[j][2];
  const ContactForce c = porewater::linear_coulomb_contact(
      delx, dely, delz, rsq, radi, radj, atom->v[i], atom->v[j], atom->omega[i], atom->omega[j],
      kn_ij[itype][jtype], kt_ij[itype][jtype], mu_ij[itype][jtype], lever, 0, dt, xi);
  fforce = c.ccel;
  svector[0] = c.ft[0];
  svector[1] = c.ft[1];
  svector[2] = c.ft[2];
  svector[3] = sqrt(c.ft[0] * c.ft[0] + c.ft[1] * c.ft[1] + c.ft[2] * c.ft[2]);
  return porewater::contact_energy(kn_ij[itype][jtype], kt_ij[itype][jtype], c, xi);
}

/* ---------------------------------------------------------------------- */

void *PairLinearCoulomb::extract(const char *str, int &dim)
{
  dim = 2;
  if (strcmp(str, "kn") == 0) return (void *) kn_ij;
  if (strcmp(str, "kt") == 0) return (void *) kt_ij;
  if (strcmp(str, "mu") == 0) return (void *) mu_ij;
  dim = 0;
  if (strcmp(str, "lever") == 0) return (void *) &lever;
  return nullptr;
}
