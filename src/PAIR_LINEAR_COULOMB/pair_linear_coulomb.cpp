/* ----------------------------------------------------------------------
   pair_style linear/coulomb (see doc/pair_linear_coulomb.rst)
------------------------------------------------------------------------- */

#include "pair_linear_coulomb.h"

#include "contact/contact_block.h"
#include "lammps_compat.h"
#include "lammps_input.h"

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
using porewater::ContactCoeffs;
using porewater::ContactForce;

/* ---------------------------------------------------------------------- */

PairLinearCoulomb::PairLinearCoulomb(LAMMPS *lmp) :
    PairGranHookeHistory(lmp), dissipated(0.0), uniform_coeffs(-1), kn_ij(nullptr),
    kt_ij(nullptr), mu_ij(nullptr)
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
  // and the steps without energy, virial or dissipation to count (most) skip that code
  const bool tally = evflag || style.dissipation;
  if (!uniform_coeffs)
    tally ? eval<MIXED, 1>() : eval<MIXED, 0>();
  else if (porewater::is_frictionless(kt_ij[1][1], mu_ij[1][1]))
    tally ? eval<UNIFORM_FRICTIONLESS, 1>() : eval<UNIFORM_FRICTIONLESS, 0>();
  else
    tally ? eval<UNIFORM_FRICTIONAL, 1>() : eval<UNIFORM_FRICTIONAL, 0>();
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
             x[j][1], x[j][2], overlap, style.overlap_limit);
}

bool PairLinearCoulomb::coefficients_are_uniform() const
{
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = 1; j <= atom->ntypes; j++)
      if (kn_ij[i][j] != kn_ij[1][1] || kt_ij[i][j] != kt_ij[1][1] || mu_ij[i][j] != mu_ij[1][1])
        return false;
  return true;
}

porewater::ContactStep PairLinearCoulomb::contact_step() const
{
  return porewater::ContactStep{style.lever, update->setupflag ? 0 : 1, dt};
}

/* ----------------------------------------------------------------------
   the host side of the sweep: LAMMPS' per-atom arrays, paged neighbor list and history,
   forces added in place in the order of gran/hooke/history (so that `lever radius`
   reproduces it bit for bit), energy and virial through Pair::ev_tally_xyz
------------------------------------------------------------------------- */

template <int MODE, int TALLY> struct PairLinearCoulomb::Sweep {
  static constexpr bool UNIFORM = MODE != MIXED;
  struct Sums {
    double lost = 0.0;
  };
  struct Row {
    const int *jlist;
    int jnum;
    int *flags;
    double *springs;
    int count() const { return jnum; }
    int neighbor(int jj) const { return jlist[jj] & NEIGHMASK; }
    int touched(int jj) const { return flags[jj]; }
    void touch(int jj) const { flags[jj] = 1; }
    void forget(int jj) const
    {
      flags[jj] = 0;
      springs[3 * jj] = springs[3 * jj + 1] = springs[3 * jj + 2] = 0.0;
    }
    double *history(int jj, double *) const { return springs + 3 * jj; }
    void keep_history(int, const double *) const {}    // updated in place
  };
  // grain i's force and torque in registers while its contacts are applied: the same sums
  // in the same order as adding to f[i] in place (no contact of i's row touches f[i] as j)
  struct GrainForce {
    double *f_i, *torque_i;
    double f[3], torque[3];
    GrainForce(double *f_row, double *torque_row) : f_i(f_row), torque_i(torque_row)
    {
      for (int d = 0; d < 3; d++) {
        f[d] = f_i[d];
        torque[d] = torque_i[d];
      }
    }
    void add(const ContactForce &c, int frictional)
    {
      f[0] += c.f[0];
      f[1] += c.f[1];
      f[2] += c.f[2];
      if (frictional) {
        torque[0] -= c.tor_i[0];
        torque[1] -= c.tor_i[1];
        torque[2] -= c.tor_i[2];
      }
    }
    void finish() const
    {
      for (int d = 0; d < 3; d++) {
        f_i[d] = f[d];
        torque_i[d] = torque[d];
      }
    }
  };

  PairLinearCoulomb *pair;
  const int *ilist;
  // LAMMPS' per-atom 3-vectors are contiguous (row i at [3 i]): one load, not two, per value
  const double *xs, *vs, *omegas;
  double *fs, *torques;
  const double *radii;
  const int *types;
  const int *numneigh;
  int **firstneigh, **firsttouch;
  double **firstxi;
  double **kn, **kt, **mu;
  ContactCoeffs uniform;
  porewater::ContactStep contact;
  double limit;
  int nlocal, newton_pair, tracking;

  int grain(int ii) const { return ilist[ii]; }
  bool uniform_coeffs(ContactCoeffs &k) const
  {
    k = coeffs(1, 1);
    return UNIFORM;
  }
  double x(int i, int d) const { return xs[3 * static_cast<long>(i) + d]; }
  double radius(int i) const { return radii[i]; }
  int type(int i) const { return UNIFORM ? 1 : types[i]; }
  Row neighbors(int i) const { return Row{firstneigh[i], numneigh[i], firsttouch[i], firstxi[i]}; }
  const double *v(int i, double *) const { return vs + 3 * static_cast<long>(i); }
  const double *omega(int i, double *) const { return omegas + 3 * static_cast<long>(i); }
  ContactCoeffs coeffs(int itype, int jtype) const
  {
    if (UNIFORM)    // frictional known at compile time: the frictionless path has no spring
      return ContactCoeffs{uniform.kn, uniform.kt, uniform.mu, MODE == UNIFORM_FRICTIONAL};
    return porewater::contact_coeffs(kn[itype][jtype], kt[itype][jtype], mu[itype][jtype]);
  }
  porewater::ContactStep step() const { return contact; }
  bool owns(int j) const { return newton_pair || j < nlocal; }
  double share(int j) const { return porewater::pair_share(j, nlocal, newton_pair); }
  GrainForce force_on(int i) const
  {
    return GrainForce{fs + 3 * static_cast<long>(i), torques + 3 * static_cast<long>(i)};
  }
  void add_reaction(int j, const ContactForce &c, int frictional) const
  {
    double *f_j = fs + 3 * static_cast<long>(j);
    f_j[0] -= c.f[0];
    f_j[1] -= c.f[1];
    f_j[2] -= c.f[2];
    if (frictional) {
      double *torque_j = torques + 3 * static_cast<long>(j);
      torque_j[0] -= c.tor_j[0];
      torque_j[1] -= c.tor_j[1];
      torque_j[2] -= c.tor_j[2];
    }
  }
  double overlap_limit() const { return limit; }
  void broken(int i, int j, double overlap) const { pair->broken_contact(i, j, overlap); }
  bool tracks_dissipation() const { return TALLY && tracking; }
  void add_loss(Sums &sums, double energy) const { sums.lost += energy; }
  void tally(Sums &, int i, int j, const ContactForce &c, const ContactCoeffs &k,
             const double *xi, double delx, double dely, double delz) const
  {
    if (TALLY && pair->evflag)
      pair->ev_tally_xyz(i, j, nlocal, newton_pair,
                         pair->eflag_either ? porewater::contact_energy(k.kn, k.kt, c, xi) : 0.0,
                         0.0, c.f[0], c.f[1], c.f[2], delx, dely, delz);
  }
};

template <int MODE, int TALLY> void PairLinearCoulomb::eval()
{
  // the first row of a per-atom 3-vector (none on a rank without atoms)
  auto data = [](double **a) { return a ? a[0] : nullptr; };
  const Sweep<MODE, TALLY> sweep{this,
                          list->ilist,
                          data(atom->x),
                          data(atom->v),
                          data(atom->omega),
                          data(atom->f),
                          data(atom->torque),
                          atom->radius,
                          atom->type,
                          list->numneigh,
                          list->firstneigh,
                          fix_history->firstflag,
                          fix_history->firstvalue,
                          kn_ij,
                          kt_ij,
                          mu_ij,
                          porewater::contact_coeffs(kn_ij[1][1], kt_ij[1][1], mu_ij[1][1]),
                          contact_step(),
                          style.overlap_limit,
                          atom->nlocal,
                          force->newton_pair,
                          style.dissipation ? 1 : 0};
  typename Sweep<MODE, TALLY>::Sums sums;
  porewater::ContactBlock block;
  porewater::linear_coulomb_block_sweep(sweep, 0, list->inum, sums, block);
  dissipated += sums.lost;
}

/* ---------------------------------------------------------------------- */

void PairLinearCoulomb::settings(int narg, char **arg)
{
  style = porewater::parse_or_stop(lmp, "pair_style linear/coulomb", narg, arg,
                                   porewater::parse_linear_coulomb);
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
  if (narg < 2) error->all(FLERR, "Illegal pair_coeff linear/coulomb command: expected I J kn kt mu");
  allocate_coeffs();
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  const ContactCoeffs k = porewater::parse_or_stop(lmp, "pair_coeff linear/coulomb", narg - 2,
                                                   arg + 2, porewater::parse_linear_coulomb_coeffs);
  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      kn_ij[i][j] = k.kn;
      kt_ij[i][j] = k.kt;
      mu_ij[i][j] = k.mu;
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0) error->all(FLERR, "Illegal pair_coeff linear/coulomb command: no type pair matched");
}

/* ---------------------------------------------------------------------- */

void PairLinearCoulomb::init_style()
{
  if (!porewater::has_sphere_attributes(atom))
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
  const int lever = style.lever, dissipation = style.dissipation ? 1 : 0;
  fwrite(&lever, sizeof(int), 1, fp);
  fwrite(&dissipation, sizeof(int), 1, fp);
  fwrite(&style.overlap_limit, sizeof(double), 1, fp);
}

void PairLinearCoulomb::read_restart_settings(FILE *fp)
{
  int flags[2] = {0, 0};
  if (comm->me == 0) {
    utils::sfread(FLERR, flags, sizeof(int), 2, fp, nullptr, error);
    utils::sfread(FLERR, &style.overlap_limit, sizeof(double), 1, fp, nullptr, error);
  }
  MPI_Bcast(flags, 2, MPI_INT, 0, world);
  MPI_Bcast(&style.overlap_limit, 1, MPI_DOUBLE, 0, world);
  style.lever = flags[0];
  style.dissipation = flags[1] != 0;
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
  const porewater::ContactPair pair = porewater::contact_pair(
      delx, dely, delz, rsq, radi, radj, atom->v[i], atom->v[j], atom->omega[i], atom->omega[j]);
  const porewater::ContactStep setup_step{style.lever, 0, dt};
  const ContactForce c = porewater::linear_coulomb_contact(
      pair, porewater::contact_coeffs(kn_ij[itype][jtype], kt_ij[itype][jtype], mu_ij[itype][jtype]),
      setup_step, xi);
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
  if (strcmp(str, "lever") == 0) return (void *) &style.lever;
  return nullptr;
}
