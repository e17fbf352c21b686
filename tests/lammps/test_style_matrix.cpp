// The per-style matrix (style_matrix.h) for each style of the plugin: its scenes, the
// observables compared with their tolerances and the reasons for them, and its bad inputs
// with the message each must give. The styles' physics is tested in their own test_*.cpp.
#include "darcy_inputs.h"
#include "fix_walls_inputs.h"
#include "granular_inputs.h"
#include "style_matrix.h"

namespace pwtest {
namespace {

// a case for `style` (fix `fix_id`, or a pair style if empty); lattice: see StyleCase
StyleCase named(const std::string &name, const std::string &style, const std::string &fix_id,
                double lattice)
{
  StyleCase c;
  c.name = name;
  c.style = style;
  c.fix_id = fix_id;
  c.lattice = lattice;
  return c;
}

StyleCase pair_linear_coulomb()
{
  StyleCase c = named("PairLinearCoulomb", "linear/coulomb", "", dense_gas_spacing);
  c.observables = {
      // /kk: forces summed in another order, round-off amplified over 1000 steps of a dense
      // flow with reneighboring (measured 3e-13 of a diameter once this LAMMPS' KOKKOS
      // neighbor history is patched, 2e-3 before); a Coulomb branch flipped by round-off
      // would show as 1e-7. MPI: another ghost and neighbor order, another summation order:
      // round-off amplified by 300 steps of a dense gas stays below 1e-9 of a diameter
      per_atom("x", 1e-10, 1e-9),
      // the kinetic energy to the same round-off (not compared over MPI)
      value("ke", 1e-10, NOT_COMPARED).relative_to_largest(),
  };
  const std::string pair = "pair_style linear/coulomb\npair_coeff * * 2000.0 2000.0 0.5\n";
  c.kokkos = {chute(), "pair_style linear/coulomb\npair_coeff * * 200000.0 200000.0 0.5\n", 1000};
  c.mpi = {dense_gas(6), pair, 300};
  // the pair style and its coefficients come back from the restart file; the histories
  // must too (on KOKKOS they did not before scripts/patches/lammps-kokkos-neigh-history.patch)
  c.restart = {{dense_gas(6), pair, 150}, "", dense_gas_settings(), ""};

  c.bad_scene = dense_gas(3);
  const std::string style = "pair_style linear/coulomb\n";
  const std::string atomic = "units lj\natom_style atomic\nregion b block 0 4 0 4 0 4\ncreate_box 1 b\n"
                             "create_atoms 1 single 1 1 1\nmass 1 1.0\n";
  c.bad_inputs = {
      {"pair_style linear/coulomb lever middle", "lever expects contact or radius, got 'middle'"},
      {"pair_style linear/coulomb damping 1",
       "unknown keyword 'damping' (allowed: lever, dissipation, overlap_limit)"},
      {"pair_style linear/coulomb dissipation maybe", "dissipation expects yes or no, got 'maybe'"},
      {"pair_style linear/coulomb overlap_limit 0", "overlap_limit expects a number in (0, 2], got '0'"},
      {"pair_coeff * * 1000.0 1000.0", "expected I J kn kt mu", style},
      {"pair_coeff * * -1000.0 1000.0 0.5", "kn expects a finite number > 0, got '-1000.0'", style},
      {"pair_coeff * * 1000.0 -1.0 0.5", "kt expects a finite number >= 0, got '-1.0'", style},
      {"pair_coeff * * 1000.0 1000.0 -0.5", "mu expects a finite number >= 0, got '-0.5'", style},
      // accepted as written, refused when the run starts
      {"run 0", "atom_style sphere", style + "pair_coeff * * 1000.0 1000.0 0.5\n", atomic},
      {"run 0", "requires newton off", "newton on\n" + style + "pair_coeff * * 1000.0 1000.0 0.5\n",
       "", BadInput::kokkos},
  };
  return c;
}

// `options`: more keywords of the fix in every scene
StyleCase fix_darcy_pressure(const std::string &options = "")
{
  StyleCase c = named("FixDarcyPressure", "darcy/pressure", "fl", 0.01);
  c.observables = {
      // /kk: the same stencil functions in the same order on one thread: round-off at most.
      // MPI: deposits and contact forces summed in another order: round-off, not amplified
      // by a lifting lattice (measured 2e-15 m); 1e-12 m is 1e-10 of a diameter
      per_atom("x", 1e-12, 1e-12),
      // p: two solves that differ by round-off agree to the CG tolerance (bed_p_agreement);
      // measured 1e-10 Pa (np 2) and 4e-7 Pa (np 3). Its mean and max over the active cells
      // differ by no more than p does
      field("pressure", bed_cells, bed_p_agreement, bed_p_agreement),
      value("f_fl[1]", bed_p_agreement, bed_p_agreement),
      value("f_fl[3]", bed_p_agreement, bed_p_agreement),
      // the fluid force on each grain, read on the host from /kk too: round-off of the
      // largest (not compared over MPI, where p differs by the CG tolerance)
      per_atom("f_fl", 1e-12, NOT_COMPARED).relative_to_largest().above(0.0),
  };
  // the bed lifted by twice the critical gradient
  const std::string fluid = bed_fluid(lifting_pressure, 2) + options +
      "\nfix move mobile nve/sphere\n";
  c.kokkos = {bed(), fluid, 400};
  c.mpi = {bed("processors * * 1"), fluid, 400};    // x-y: the bed is thin in z
  // every 3: the split at step 200 falls between fluid steps (198, 201). The restart holds
  // p, phi and the fluid clock: `initial 123` must be ignored
  const std::string every3 = bed_fluid(lifting_pressure, 3) + options;
  c.restart = {{bed(), every3 + "\nfix move mobile nve/sphere\n", 200},
               "",
               "comm_modify vel yes\nneighbor 0.002 bin\nneigh_modify delay 0 every 1 check yes\n"
               "timestep 2.5e-5\nfix weight mobile gravity 9.81 vector 0 0 -1\n",
               every3 + " initial 123\nfix move mobile nve/sphere\n"};

  c.bad_scene = empty_column(1.0);
  const std::string fix = "fix bad all darcy/pressure grid 2 2 4", unit = unit_diffusivity;
  c.bad_inputs = {
      {"fix bad all darcy/pressure grid 2 2 2" + unit, "non-periodic in z", "",
       "units lj\natom_style sphere\nregion box block 0 1 0 1 0 1\ncreate_box 1 box\n"},
      {"fix bad all darcy/pressure grid 2 2 2" + unit, "requires atom_style sphere", "",
       "units lj\natom_style atomic\nboundary p p f\nregion box block 0 1 0 1 0 1\ncreate_box 1 box\n"},
      {fix + " viscosity 1 density 1 permeability 1", "missing required keyword(s): compressibility"},
      {fix + unit + " porosity 0.2 1.0", "porosity MIN MAX needs 0 < MIN <= MAX < 1"},
      {fix + unit + " bottom closed", "bottom expects noflow, a finite number or v_name, got 'closed'"},
      {fix + unit + " top closed", "top expects noflow, a finite number or v_name, got 'closed'"},
      {fix + unit + " every 0", "every expects an integer >= 1, got '0'"},
      {fix + unit + " viscosity -1", "viscosity expects a finite number > 0, got '-1'"},
      {fix + unit + " gravity 0 0", "gravity expects a finite number, but the command ends there"},
      {fix + unit + " damping 1", "unknown keyword 'damping' (allowed: grid, viscosity,"},
      {"fix bad all darcy/pressure grid 2 0 4" + unit, "grid expects an integer >= 1, got '0'"},
      {fix + unit + " interpolate always", "interpolate expects step or fluid, got 'always'"},
      {fix + unit + " variables time", "variables expects atoms or global, got 'time'"},
      {"run 0", "variables global, but variable top_p for top reads per-atom data (pe, a "
                "thermo keyword over the atoms in variable pe_top)",
       "variable pe_top equal pe\nvariable top_p equal v_pe_top\n" + fix + unit +
           " top v_top_p variables global\n"},
      {fix + unit + " novertical", "novertical expects a group ID, but the command ends there"},
      // groups are looked up when the run starts
      {"run 0", "novertical group nope does not exist", fix + unit + " novertical nope\n"},
      // variables are checked when the run starts
      {"run 0", "variable nowhere for top does not exist", fix + unit + " top v_nowhere\n"},
      {"run 0", "variable atomic for ztop is not equal-style",
       "variable atomic atom x\n" + fix + unit + " ztop v_atomic\n"},
      // a solve that cannot reach its tolerance stops the run and says why
      {"run 1", "the pressure solve did not converge in 1 iterations",
       fix + unit + " initial 1.0 tol 1e-14 maxiter 1\ntimestep 1e-3\n"},
  };
  return c;
}

// fix darcy/pressure with more keywords (`options`) in the same scenes: /kk, MPI and the
// restart split as the default, and the options' own bad inputs (`bad`, after the command)
StyleCase fix_darcy_pressure_with(const std::string &name, const std::string &options,
                                  const std::vector<std::pair<std::string, std::string>> &bad)
{
  StyleCase c = fix_darcy_pressure(options);
  c.name = name;
  c.bad_inputs.clear();
  for (const auto &b : bad)
    c.bad_inputs.push_back({"fix bad all darcy/pressure grid 2 2 4" + unit_diffusivity + b.first, b.second});
  return c;
}

// `options`: the wall's dashpot keywords, on the /kk and MPI scenes
StyleCase fix_wall_stress(const std::string &name, const std::string &kokkos_options,
                          const std::string &mpi_options)
{
  StyleCase c = named(name, "wall/stress", "w", 1.0);
  // /kk: the same arithmetic per grain, sums in another order; MPI: reductions and neighbor
  // lists in another order. Round-off either way, which the damped stack does not amplify
  c.observables = {
      value("f_w[1]", 1e-12, 1e-12),                  // the wall's z, of order 4
      value("f_w[2]", 1e-10, 1e-10).above(1e-4),      // its velocity: the stack still rings
      value("f_w[3]", 1e-9, 1e-9),                    // the stress of the grains, of order 10
      value("f_w[4]", 0.0, 0.0),                      // applied: v_s of the step, exact
      value("f_w[5]", 1e-9, 1e-9),                    // the grain dashpots' share of 3
      value("f_w[6]", 1e-9, 1e-9),                    // the plate dashpot, per area
      per_atom("x", 1e-12, 1e-12),
  };
  // the stack under an oscillating stress, still ringing: a moving wall in contact
  const std::string stack = oscillating_stress +
      cubic_stack(3, 3, 4, 8.0, STACK_KN) + "timestep 5e-4\n";
  const std::string wall = wall_on_stack("v_s", 9, kokkos_options);
  c.kokkos = {stack, wall + "fix_modify w virial yes\n", 3000};
  c.mpi = {oscillating_stress + cubic_stack(6, 6, 5, 9.0) + "timestep 5e-4\n",
           wall_on_stack("v_s", 36, mpi_options), 1000};
  // `auto` is ignored after read_restart: the file holds the wall's position, velocity and force
  c.restart = {{stack, wall, 1500},
               "newton off\n",
               oscillating_stress +
                   "comm_modify vel yes\nneighbor 0.2 bin\nneigh_modify delay 0 every 1 check yes\n",
               wall};

  c.bad_scene = empty_box;
  const std::string fix = "fix w all wall/stress ";
  c.bad_inputs = {
      {fix + "z 8 stress 0.5 mass 6", "missing required keyword(s): kn"},
      {fix + "z 8 stress 0.5 mass 6 kn", "kn expects a number > 0, but the command ends there"},
      {fix + "z 8 stress 0.5 mass -6 kn 100", "mass expects a finite number > 0, got '-6'"},
      {fix + "z top stress 0.5 mass 6 kn 100", "z expects auto or a finite number, got 'top'"},
      {fix + "z 8 stress high mass 6 kn 100", "stress expects a finite number or v_name, got 'high'"},
      {fix + "z 8 stress 0.5 mass 6 kn stiff", "kn expects a finite number > 0, got 'stiff'"},
      {fix + "z 8 stress 0.5 mass 6 kn 0", "kn expects a finite number > 0, got '0'"},
      {fix + "z 8 stress 0.5 mass 6 kn 100 damping -1", "damping expects a finite number >= 0, got '-1'"},
      {fix + "z 8 stress 0.5 mass 6 kn 100 wiggle 1",
       "unknown keyword 'wiggle' (allowed: z, stress, mass, kn, damping, damping_velocity, "
       "plate_damping, variables)"},
      {fix + "z 8 stress 0.5 mass 6 kn 100 variables time",
       "variables expects atoms or global, got 'time'"},
      {"variable top equal 2+0.5*bound(all,zmax)\n" + fix +
           "z 8 stress v_top mass 6 kn 100 variables global\nrun 0",
       "variables global, but variable top for stress reads per-atom data (bound(), a group "
       "function); give variables atoms"},
      {fix + "z 8 stress v_nope mass 6 kn 100\nrun 0", "variable nope for stress does not exist"},
      {"variable perat atom x\n" + fix + "z 8 stress v_perat mass 6 kn 100\nrun 0",
       "variable perat for stress is not equal-style"},
      {fix + "z auto stress 1 mass 6 kn 100\nrun 0", "z auto needs grains"},
      // pulled up (S < 0) it leaves through the top: a = 1, z = 8 + t²/2 passes 10 at t = 2
      {fix + "z 8 stress -1 mass 6 kn 100\nrun 300", "above the box top 10"},
      {fix + "z 1 stress 1 mass 6 kn 100\nrun 300", "below the box bottom 0"},
      // a stress that overflows makes the wall's velocity infinite in the first step
      {"variable inf equal 1e308*10\n" + fix + "z 8 stress v_inf mass 6 kn 100\nrun 10",
       "the wall ran away at step 1: z = -inf, v = -inf"},
      {"fix w all wall/stress z 8 stress 0.5 mass 6 kn 100",
       "needs a z-bounded box: boundary f, fm or fs in z", "",
       "units lj\natom_style sphere\nboundary p p p\nregion box block 0 2 0 3 0 10\ncreate_box 1 box\n"},
  };
  return c;
}

StyleCase fix_shear_stress()
{
  StyleCase c = named("FixShearStress", "shear/stress", "s", 1.0);
  c.observables = {
      // frictional contacts summed in another order (/kk) or over ranks (MPI): round-off,
      // amplified by 1000-2000 steps of sticking and slipping springs
      per_atom("x", 1e-10, 1e-10),
      value("f_s[2]", 1e-10, 1e-10).above(1e-4),    // the plate's displacement: it moved
      value("f_s[1]", 1e-9, 1e-9),                  // its velocity
      value("f_s[3]", 1e-8, 1e-8),                  // the stress resisting it, of order 3
  };
  // the plate pressed by the wall and sheared at τ = 3 < μσ
  c.kokkos = {pressed_layer(3), shear_plate(3.0, 3), 2000};
  c.mpi = {pressed_layer(6), shear_plate(3.0, 6), 1000};
  c.restart = {{pressed_layer(3), shear_plate(3.0, 3), 1000},
               "newton off\n",
               "comm_modify vel yes\nneighbor 0.2 bin\nneigh_modify delay 0 every 1 check yes\n",
               "fix integrate mobile nve/sphere\n" + plate_wall(3) + shear_plate(3.0, 3)};

  c.bad_scene = free_layer("nve/sphere");
  const std::string fix = "fix s all shear/stress ";
  c.bad_inputs = {
      {fix + "tau 0.5", "missing required keyword(s): mass"},
      {fix + "tau 0.5 mass", "mass expects a number > 0, but the command ends there"},
      {fix + "tau 0.5 mass 0", "mass expects a finite number > 0, got '0'"},
      {fix + "tau v_tau mass 1", "tau expects a finite number, got 'v_tau'"},
      {fix + "tau 0.5 mass 1 lock y", "unknown keyword 'lock' (allowed: tau, mass)"},
      {"group none empty\nfix s none shear/stress tau 0.5 mass 1\nrun 0", "group none has no grains"},
      // a = 2400: the plate moves a·n·Δt² in step n, more than half the skin (0.1) at n ≈ 42
      {fix + "tau 1200 mass 12\nrun 100", "the plate ran away at step"},
  };
  return c;
}

// the frictional dense gas integrated by `integrator`, fix integrate
StyleCase fix_nve_sphere_ty3(const std::string &name, const std::string &integrator)
{
  StyleCase c = named(name, "nve/sphere/ty3", "integrate", dense_gas_spacing);
  c.observables = {
      // contacts summed in another order (/kk), or over ranks that grains cross, taking
      // their a_prev along (MPI): round-off amplified by 300 steps of a dense gas
      per_atom("x", 1e-9, 1e-9),
      per_atom("omega", 1e-7, NOT_COMPARED),
      // compared in the restart test only
      value("ke", NOT_COMPARED, NOT_COMPARED),
      value("c_erot", NOT_COMPARED, NOT_COMPARED),
  };
  const std::string gas = frictional_gas() + "unfix integrate\n";
  const std::string fix = "fix integrate all " + integrator + "\n";
  c.kokkos = {gas, fix, 300};
  c.mpi = {gas, fix, 300};
  // control: another fix ID finds no history in the file and restarts with ȧ = 0
  c.restart = {{gas, fix, 150}, "", dense_gas_settings() + "unfix integrate\n", fix,
               "fix fresh all " + integrator + "\n", 1e-8};
  c.bad_scene = dense_gas(3);
  return c;
}

// the loose bed settling onto its held base and the floor under fix nve/sphere/bed
StyleCase fix_nve_sphere_bed()
{
  StyleCase c = named("FixNVESphereBed", "nve/sphere/bed", "grains", 1.05);
  c.observables = {
      // frictional contacts summed in another order (/kk) or over ranks (MPI): round-off
      // amplified by 1000 steps of a bed falling onto its base
      per_atom("x", 1e-9, 1e-9),
      per_atom("v", 1e-8, 1e-8),
      per_atom("omega", 1e-7, NOT_COMPARED),
  };
  const std::string fix = "fix grains all nve/sphere/bed held bottom gravity 1.0 bed floor 0.0 2000\n";
  c.kokkos = {loose_bed(), fix, 1000};
  c.mpi = {loose_bed(), fix, 1000};
  // no state of its own: the restart carries the grains and the groups it names
  c.restart = {{loose_bed(), fix, 500},
               "newton off\n",
               "comm_modify vel yes\nneighbor 0.2 bin\nneigh_modify delay 0 every 1 check yes\n",
               fix};
  c.bad_scene = loose_bed(3, 3);
  const std::string bed = "fix grains all nve/sphere/bed ";
  c.bad_inputs = {
      {bed + "drag 1", "unknown keyword 'drag' (allowed: held, gravity, floor, fuse)"},
      {bed + "fuse maybe", "fuse expects yes or no, got 'maybe'"},
      {bed + "held", "held expects a group ID, but the command ends there"},
      {bed + "held base", "held names group base, which does not exist"},
      {bed + "gravity down bed", "gravity expects a finite number, got 'down'"},
      {bed + "gravity 1.0", "gravity group expects a group ID, but the command ends there"},
      {bed + "gravity 1.0 sand", "gravity names group sand, which does not exist"},
      {bed + "floor 0.0", "floor kn expects a number > 0, but the command ends there"},
      {bed + "floor 0.0 -5", "floor kn expects a finite number > 0, got '-5'"},
      {bed + "floor low 2000", "floor expects a finite number, got 'low'"},
      {bed + "floor 0.0 2000", "requires atom_style sphere", "",
       "units lj\natom_style atomic\nregion b block 0 4 0 4 0 4\ncreate_box 1 b\n"},
  };
  return c;
}

std::vector<StyleCase> cases()
{
  StyleCase ty3 = fix_nve_sphere_ty3("FixNVESphereTY3", "nve/sphere/ty3");
  ty3.bad_inputs = {
      {"fix t all nve/sphere/ty3 disc", "unknown keyword 'disc' (allowed: corrector)"},
      {"fix t all nve/sphere/ty3", "requires atom_style sphere", "",
       "units lj\natom_style atomic\nregion b block 0 4 0 4 0 4\ncreate_box 1 b\n"},
  };
  StyleCase corrected = fix_nve_sphere_ty3("FixNVESphereTY3Corrector", "nve/sphere/ty3 corrector yes");
  corrected.bad_inputs = {
      {"fix t all nve/sphere/ty3 corrector", "corrector expects yes or no, but the command ends there"},
      {"fix t all nve/sphere/ty3 corrector maybe", "corrector expects yes or no, got 'maybe'"},
  };
  // the original's lab-frame grain dashpot and a dashpot on the plate itself
  StyleCase dashpots = fix_wall_stress("FixWallStressDashpots",
                                       "damping_velocity absolute plate_damping 300",
                                       "damping_velocity absolute plate_damping 1000");
  const std::string fix = "fix w all wall/stress z 8 stress 0.5 mass 6 kn 100 ";
  dashpots.bad_inputs = {
      {fix + "damping_velocity lab", "damping_velocity expects relative or absolute, got 'lab'"},
      {fix + "plate_damping -2", "plate_damping expects a finite number >= 0, got '-2'"},
      {fix + "plate_damping soft", "plate_damping expects a finite number >= 0, got 'soft'"},
  };
  // `solver relaxed`, the original program's iteration (the sweeps are one more
  // deterministic function of the same deposits)
  StyleCase relaxed = fix_darcy_pressure_with(
      "FixDarcyPressureRelaxed", " solver relaxed 0.05 1e-3",
      {{" solver exact", "solver expects converged or relaxed, got 'exact'"},
       {" solver relaxed 0 1e-3", "solver expects a number in (0, 1], got '0'"},
       {" solver relaxed 0.05", "solver expects a number > 0, but the command ends there"}});
  // `seepage full`, the grains taking the water's whole force -V grad p/(1 - phi) (the factor
  // is one more function of the same stencil and cell porosities)
  StyleCase seepage = fix_darcy_pressure_with(
      "FixDarcyPressureSeepageFull", " seepage full",
      {{" seepage drag", "seepage expects pressure or full, got 'drag'"},
       {" seepage", "seepage expects pressure or full, but the command ends there"}});
  return {pair_linear_coulomb(), fix_darcy_pressure(), relaxed, seepage,
          fix_wall_stress("FixWallStress", "", ""),
          dashpots, fix_shear_stress(), ty3, corrected, fix_nve_sphere_bed()};
}

}    // namespace

INSTANTIATE_TEST_SUITE_P(Styles, StyleMatrix, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<StyleCase> &info) {
                           return info.param.name;
                         });

}    // namespace pwtest
