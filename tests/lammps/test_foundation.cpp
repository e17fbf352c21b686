// The build itself: our LAMMPS runs native granular styles through the library
// interface, plain and with KOKKOS (OpenMP), with the plugin loaded.
#include "granular_inputs.h"
#include "lammps_fixture.h"

#include "force.h"
#include "pair.h"

#include <gtest/gtest.h>

#include <cmath>

using pwtest::Accel;
using pwtest::Lammps;

namespace {

struct Outcome {
  double ke, erot, natoms;
  std::map<long, std::vector<double>> x;
};

Outcome run_native_gas(Accel accel)
{
  Lammps l(accel);
  l.commands(pwtest::dense_gas(6));
  l.command("pair_style gran/hooke/history 2000.0 NULL 0.0 NULL 0.5 0");
  l.command("pair_coeff * *");
  l.command("run 200");
  return {l.thermo("ke"), l.equal("c_erot"), l.thermo("atoms"), l.unwrapped()};
}

}    // namespace

TEST(Foundation, PluginLoadsAndRegistersItsStyles)
{
  Lammps l;
  // `plugin load` ran in the constructor; the styles are now known to LAMMPS
  l.commands(pwtest::dense_gas(3));
  EXPECT_NO_THROW(l.command("pair_style linear/coulomb"));
  EXPECT_STREQ(l.lmp->force->pair_style, "linear/coulomb");
}

TEST(Foundation, NativeGranularRuns)
{
  const Outcome plain = run_native_gas(Accel::none);
  EXPECT_EQ(plain.natoms, 216);
  // 200 undamped steps conserve energy up to integration error; KE stays O(initial)
  EXPECT_TRUE(std::isfinite(plain.ke) && plain.ke > 0.0);
  EXPECT_GT(plain.erot, 0.0);    // friction spun the grains up
}

TEST(Foundation, NativeGranularKokkosEqualsPlain)
{
  PW_SKIP_WITHOUT_KOKKOS();
  const Outcome plain = run_native_gas(Accel::none);
  const Outcome kk = run_native_gas(Accel::kokkos);
  EXPECT_EQ(kk.natoms, 216);
  // same input, same physics: host KOKKOS and CPU differ by summation order only,
  // which 200 steps of a dense gas amplify to well below 1e-6 of the grain size
  EXPECT_LT(pwtest::max_abs_diff(plain.x, kk.x), 1e-6);
  EXPECT_NEAR(kk.ke, plain.ke, 1e-6 * plain.ke);
}
