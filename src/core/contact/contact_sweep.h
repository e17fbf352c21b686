// The bookkeeping of pair linear/coulomb around its contact law, written once: open pairs
// forget their spring (open_pair), closed ones get the law, and then the spring is kept, the
// broken-contact check made, the dissipation counted, and the force and torque scattered to
// both grains (closed_contact). One grain's pass (linear_coulomb_sweep, the GPU's) and the
// block pass of SIMD hosts (contact_block.h) are made of these pieces. The host loops over
// grains (a for loop on the CPU, a Kokkos kernel for /kk) and says through its policy P where
// the data live and where the results go:
//
//   P::Sums                  what the loop accumulates (at least the dissipated energy)
//   p.x(i, d), p.radius(i), p.type(i)
//   p.neighbors(i)           a row: count, neighbor(jj), touched(jj), touch(jj),
//                            forget(jj) (clears flag and spring), history(jj, scratch)
//                            (pointer to the spring: in place or loaded into scratch),
//                            keep_history(jj, xi) (stores it back if it was loaded)
//   p.v(i, scratch), p.omega(i, scratch)   pointers to a grain's velocities
//   p.coeffs(itype, jtype)   ContactCoeffs of the type pair
//   p.step()                 ContactStep of this step
//   p.owns(j), p.share(j)    whether f_j is added here; this rank's share of the pair's energy
//   p.force_on(i)            an accumulator for grain i: add(c, frictional), finish()
//   p.add_reaction(j, c, frictional)       −f and −ℓ_j tor on j
//   p.overlap_limit(), p.broken(i, j, overlap)
//   p.tracks_dissipation(), p.add_loss(sums, energy)
//   p.tally(sums, i, j, c, k, xi, delx, dely, delz)   energy and virial of the pair
#ifndef PW_CONTACT_SWEEP_H
#define PW_CONTACT_SWEEP_H

#include "contact/linear_coulomb.h"

namespace porewater {

// An open pair forgets its spring, counting the energy it held (most stay apart: no stores).
template <class P, class Row>
PW_FORCEINLINE void open_pair(const P &p, const Row &row, const int jj, const int itype,
                              const int j, typename P::Sums &sums)
{
  if (row.touched(jj)) {    // flag 0 means history 0
    if (p.tracks_dissipation()) {
      double spring[3];
      p.add_loss(sums, p.share(j) *
                     opening_loss(p.coeffs(itype, p.type(j)).kt, row.history(jj, spring)));
    }
    row.forget(jj);
  }
}

// What the force of a closed contact does once the law has given it: the broken-contact
// check, the spring kept, the dissipation counted, the force and torque on both grains (on
// j only if this rank owns the pair's force on it), the energy and virial tallied.
template <class P, class Row, class GrainForce>
PW_FORCEINLINE void closed_contact(const P &p, const Row &row, GrainForce &force_i,
                                   typename P::Sums &sums, const int i, const int j, const int jj,
                                   const ContactCoeffs &k, const ContactForce &c, const double *xi,
                                   const double radi, const double radj, const double delx,
                                   const double dely, const double delz)
{
  if (contact_is_broken(c.overlap, radi, radj, p.overlap_limit())) p.broken(i, j, c.overlap);
  row.keep_history(jj, xi);
  if (p.tracks_dissipation()) p.add_loss(sums, p.share(j) * spring_loss(k.kt, c, xi));
  force_i.add(c, k.frictional);
  if (p.owns(j)) p.add_reaction(j, c, k.frictional);
  p.tally(sums, i, j, c, k, xi, delx, dely, delz);
}

// Grain i as a pass over its neighbours sees it
struct SweptGrain {
  double x, y, z, rad;
  int type;
};
template <class P> PW_FORCEINLINE SweptGrain swept_grain(const P &p, const int i)
{
  return SweptGrain{p.x(i, 0), p.x(i, 1), p.x(i, 2), p.radius(i), p.type(i)};
}

// Its pair with neighbour jj: del = x_i − x_j, |del|², j's radius, and whether they overlap
struct NeighbourPair {
  int j;
  double delx, dely, delz, rsq, radj;
  bool closed;
};
template <class P, class Row>
PW_FORCEINLINE NeighbourPair neighbour_pair(const P &p, const SweptGrain &g, const Row &row,
                                            const int jj)
{
  const int j = row.neighbor(jj);
  const double delx = g.x - p.x(j, 0);
  const double dely = g.y - p.x(j, 1);
  const double delz = g.z - p.x(j, 2);
  const double rsq = distance_squared(delx, dely, delz);
  const double radj = p.radius(j);
  return NeighbourPair{j, delx, dely, delz, rsq, radj, pair_overlaps(rsq, g.rad + radj)};
}

// One grain's pass over its half neighbour list, each contact's law as soon as it is found:
// the GPU's (a thread a grain); hosts with SIMD cores run a block of grains at a time
// (contact_block.h) through the same pieces.
template <class P>
PW_FORCEINLINE void linear_coulomb_sweep(const P &p, const int i, typename P::Sums &sums)
{
  const SweptGrain gi = swept_grain(p, i);
  const double radi = gi.rad;
  const int itype = gi.type;
  const auto row = p.neighbors(i);
  auto force_i = p.force_on(i);
  const ContactStep step = p.step();
  const int jnum = row.count();

  for (int jj = 0; jj < jnum; jj++) {
    const NeighbourPair pr = neighbour_pair(p, gi, row, jj);
    const int j = pr.j;
    const double delx = pr.delx, dely = pr.dely, delz = pr.delz, rsq = pr.rsq, radj = pr.radj;
    if (!pr.closed) {
      open_pair(p, row, jj, itype, j, sums);
      continue;
    }
    row.touch(jj);
    const ContactCoeffs k = p.coeffs(itype, p.type(j));
    // velocities are read only for closed contacts (few of the neighbours in a granular flow)
    double vi[3], vj[3], wi[3], wj[3], spring[3];
    const ContactPair pair =
        contact_pair(delx, dely, delz, rsq, radi, radj, p.v(i, vi), p.v(j, vj), p.omega(i, wi),
                     p.omega(j, wj));
    double *xi = row.history(jj, spring);
    const ContactForce c = linear_coulomb_contact(pair, k, step, xi);
    closed_contact(p, row, force_i, sums, i, j, jj, k, c, xi, radi, radj, delx, dely, delz);
  }
  force_i.finish();
}

}    // namespace porewater

#endif
