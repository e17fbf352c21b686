// A policy of pair linear/coulomb's sweeps (contact/contact_sweep.h, contact_block.h) over
// plain arrays, as a host would give it, for the unit tests: half neighbour rows of the owned
// grains, ghosts beyond nlocal, coefficients per type pair (types 1 and 2), forces added in
// place as the CPU style adds them, and the pairs tallied and reported broken kept in order.
#ifndef PW_TEST_SWEEP_POLICY_H
#define PW_TEST_SWEEP_POLICY_H

#include "contact/contact_block.h"

#include <utility>
#include <vector>

namespace pwtest {

using namespace porewater;

struct Grains {
  std::vector<std::vector<double>> x, v, omega, f, torque;
  std::vector<double> radius;
  std::vector<int> type;
  std::vector<std::vector<int>> neighbors, touch;    // half lists of the owned grains
  std::vector<std::vector<double>> springs;          // 3 per neighbour
  int nlocal = 0;
  std::vector<std::pair<int, int>> broken, tallied;
};

struct Policy {
  Grains &g;
  ContactCoeffs k[3][3];    // per type pair (types 1, 2)
  bool uniform;
  ContactStep contact;
  double limit;    // overlap_limit
  struct Sums {
    double lost = 0.0;
  };
  struct Row {
    Grains &g;
    int i;
    int count() const { return (int) g.neighbors[i].size(); }
    int neighbor(int jj) const { return g.neighbors[i][jj]; }
    int touched(int jj) const { return g.touch[i][jj]; }
    void touch(int jj) const { g.touch[i][jj] = 1; }
    void forget(int jj) const
    {
      g.touch[i][jj] = 0;
      for (int d = 0; d < 3; d++) g.springs[i][3 * jj + d] = 0.0;
    }
    double *history(int jj, double *) const { return &g.springs[i][3 * jj]; }
    void keep_history(int, const double *) const {}
  };
  struct GrainForce {    // in place, as the CPU style's sums are
    Grains &g;
    int i;
    void add(const ContactForce &c, int frictional) const
    {
      for (int d = 0; d < 3; d++) {
        g.f[i][d] += c.f[d];
        if (frictional) g.torque[i][d] -= c.tor_i[d];
      }
    }
    void finish() const {}
  };
  int grain(int ii) const { return ii; }
  bool uniform_coeffs(ContactCoeffs &c) const
  {
    c = k[1][1];
    return uniform;
  }
  double x(int i, int d) const { return g.x[i][d]; }
  double radius(int i) const { return g.radius[i]; }
  int type(int i) const { return g.type[i]; }
  Row neighbors(int i) const { return Row{g, i}; }
  const double *v(int i, double *) const { return g.v[i].data(); }
  const double *omega(int i, double *) const { return g.omega[i].data(); }
  ContactCoeffs coeffs(int itype, int jtype) const { return k[itype][jtype]; }
  ContactStep step() const { return contact; }
  bool owns(int j) const { return j < g.nlocal; }
  double share(int j) const { return pair_share(j, g.nlocal, 0); }
  GrainForce force_on(int i) const { return GrainForce{g, i}; }
  void add_reaction(int j, const ContactForce &c, int frictional) const
  {
    for (int d = 0; d < 3; d++) {
      g.f[j][d] -= c.f[d];
      if (frictional) g.torque[j][d] -= c.tor_j[d];
    }
  }
  double overlap_limit() const { return limit; }
  void broken(int i, int j, double) const { g.broken.push_back({i, j}); }
  bool tracks_dissipation() const { return true; }
  void add_loss(Sums &sums, double energy) const { sums.lost += energy; }
  void tally(Sums &, int i, int j, const ContactForce &, const ContactCoeffs &, const double *,
             double, double, double) const
  {
    g.tallied.push_back({i, j});
  }
};

// every type pair with the coefficients k, at step settings `contact`
inline Policy uniform_policy(Grains &g, const ContactCoeffs &k,
                             const ContactStep &contact = ContactStep{LEVER_CONTACT, 1, 1e-3},
                             double limit = 0.5)
{
  Policy p{g, {}, true, contact, limit};
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) p.k[a][b] = k;
  return p;
}

}    // namespace pwtest

#endif
