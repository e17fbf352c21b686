/* -*- c++ -*- ----------------------------------------------------------
   pair_style linear/coulomb: linear normal and tangential springs with a Coulomb cap,
   rotation-corrected tangential history, torque, no damping (doc/model.md §1). The law
   and its bookkeeping are the core's (contact/contact_sweep.h); this class adapts LAMMPS.
------------------------------------------------------------------------- */

#ifndef PW_PAIR_LINEAR_COULOMB_H
#define PW_PAIR_LINEAR_COULOMB_H

#include "pair_gran_hooke_history.h"

#include "input/settings.h"

namespace LAMMPS_NS {

// Reuses gran/hooke/history's neighbor-history machinery (fix NEIGH_HISTORY, granular
// neighbor list, cutoffs from radii); replaces its force law and its global coefficients
// by per-type kn, kt, mu.
class PairLinearCoulomb : public PairGranHookeHistory {
 public:
  PairLinearCoulomb(class LAMMPS *);
  ~PairLinearCoulomb() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void write_data(FILE *) override;
  void write_data_all(FILE *) override;
  double single(int, int, int, int, double, double, double, double &) override;
  void *extract(const char *, int &) override;

 protected:
  porewater::LinearCoulombSettings style;
  double dissipated;            // this rank's share since the pair style was defined
  int uniform_coeffs;           // 1: one kn, kt, mu for all type pairs; -1: not yet known
  double **kn_ij, **kt_ij, **mu_ij;   // per type pair, mixed in init_one()
  void allocate_coeffs();
  bool coefficients_are_uniform() const;
  void broken_contact(int i, int j, double overlap);
  porewater::ContactStep contact_step() const;

 private:
  enum { MIXED, UNIFORM_FRICTIONAL, UNIFORM_FRICTIONLESS };    // sweep modes
  template <int MODE, int TALLY> struct Sweep;    // the host side of porewater::linear_coulomb_block_sweep
  template <int MODE, int TALLY> void eval();
};

}    // namespace LAMMPS_NS

#endif
