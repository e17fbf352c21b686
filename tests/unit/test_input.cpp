// The one keyword reader, the styles' syntax with its defaults, and the fixes' restart
// state (src/core/input), without a host: what each bad input says, and that a state of
// another format or size is refused with a message saying how it differs.
#include "darcy/fluid.h"
#include "input/formula.h"
#include "input/keywords.h"
#include "input/restart_state.h"
#include "input/settings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

using namespace porewater;

namespace {

// the message an InputError carries, "" if none was thrown
template <class Parse> std::string message_of(const std::vector<std::string> &args, Parse parse)
{
  KeywordReader in("fix test", args);
  try {
    parse(in);
  } catch (const InputError &e) {
    return e.what();
  }
  return "";
}

}    // namespace

TEST(KeywordReader, NumbersAreWholeFiniteTokens)
{
  double v;
  EXPECT_TRUE(parse_number("1e-3", v));
  EXPECT_EQ(v, 1e-3);
  for (const char *bad : {"", "1x", "nan", "inf", "-inf", "1e999", "0x"}) EXPECT_FALSE(parse_number(bad, v)) << bad;
  int n;
  EXPECT_TRUE(parse_int("12", n));
  for (const char *bad : {"1.5", "99999999999", "", "2 "}) EXPECT_FALSE(parse_int(bad, n)) << bad;
}

TEST(KeywordReader, EveryMessageNamesTheCommandTheKeywordAndWhatItAccepts)
{
  auto wall = [](KeywordReader &in) { parse_wall_stress(in); };
  EXPECT_EQ(message_of({"z", "8", "stress", "1", "mass", "-1", "kn", "1"}, wall),
            "Illegal fix test command: mass expects a finite number > 0, got '-1'");
  EXPECT_EQ(message_of({"z", "8", "stress", "1", "mass", "1", "kn"}, wall),
            "Illegal fix test command: kn expects a number > 0, but the command ends there");
  EXPECT_EQ(message_of({"z", "up"}, wall),
            "Illegal fix test command: z expects auto or a finite number, got 'up'");
  EXPECT_EQ(message_of({"z", "8", "stress", "1", "mass", "1"}, wall),
            "Illegal fix test command: missing required keyword(s): kn");
  EXPECT_EQ(message_of({"z", "8", "spin", "1"}, wall),
            "Illegal fix test command: unknown keyword 'spin' (allowed: z, stress, mass, kn, damping, "
            "damping_velocity, plate_damping, variables)");
  auto darcy = [](KeywordReader &in) { parse_darcy(in, 0.0, 1.0); };
  EXPECT_EQ(message_of({"grid", "2", "2", "2", "viscosity", "1", "compressibility", "1", "density",
                        "1", "permeability", "1", "top", "open"},
                       darcy),
            "Illegal fix test command: top expects noflow, a finite number or v_name, got 'open'");
  EXPECT_EQ(message_of({"grid", "2", "2", "2", "vtk", "30", ""}, darcy),
            "Illegal fix test command: vtk expects a file name prefix, got ''");
  EXPECT_EQ(message_of({"grid", "2", "0", "2"}, darcy),
            "Illegal fix test command: grid expects an integer >= 1, got '0'");
  EXPECT_EQ(message_of({"grid", "2", "2", "2", "seepage", "drag"}, darcy),
            "Illegal fix test command: seepage expects pressure or full, got 'drag'");
  EXPECT_EQ(message_of({"grid", "2", "2", "2", "seepage"}, darcy),
            "Illegal fix test command: seepage expects pressure or full, but the command ends there");
  auto pair = [](KeywordReader &in) { parse_linear_coulomb(in); };
  EXPECT_EQ(message_of({"overlap_limit", "3"}, pair),
            "Illegal fix test command: overlap_limit expects a number in (0, 2], got '3'");
  EXPECT_EQ(message_of({"lever", "tip"}, pair),
            "Illegal fix test command: lever expects contact or radius, got 'tip'");
}

TEST(KeywordReader, DefaultsAreThoseOfTheDocPages)
{
  KeywordReader none("pair_style linear/coulomb", std::vector<std::string>{});
  const LinearCoulombSettings pair = parse_linear_coulomb(none);
  EXPECT_EQ(pair.lever, LEVER_CONTACT);
  EXPECT_FALSE(pair.dissipation);
  EXPECT_EQ(pair.overlap_limit, 0.5);
  KeywordReader in("fix darcy/pressure",
                   std::vector<std::string>{"grid", "2", "3", "4", "viscosity", "1e-3",
                                            "compressibility", "4e-10", "density", "1000",
                                            "permeability", "1e-12", "top", "v_ptop"});
  const DarcySettings s = parse_darcy(in, -1.0, 2.0);
  EXPECT_EQ(s.zhi, 2.0);    // the box top
  EXPECT_EQ(s.params.tol_rel, 1e-10);
  EXPECT_EQ(s.params.tol_abs, 0.0);
  EXPECT_EQ(s.params.maxiter, 1000);
  EXPECT_EQ(s.params.porosity_min, 0.1);
  EXPECT_EQ(s.params.porosity_max, 0.9);
  EXPECT_EQ(s.every, 1);
  EXPECT_EQ(s.seepage, SEEPAGE_PRESSURE);
  EXPECT_TRUE(s.interpolate_every_step);
  EXPECT_TRUE(s.top_dirichlet);
  EXPECT_EQ(s.top.variable, "ptop");
  EXPECT_FALSE(s.bottom_dirichlet);
}

TEST(RestartState, ABlockReadsBackAndAnotherFormatOrSizeIsRefused)
{
  const RestartFormat wall{RestartStyle::WallStress, 1, "fix wall/stress"};
  const std::vector<double> values = {1.5, -2.0, 3.25, 0.0};
  const std::vector<double> block = restart_block(wall, values);
  const char *bytes = (const char *) block.data();
  EXPECT_EQ(restart_values(wall, bytes, 4), values);
  auto refusal = [&](const RestartFormat &format, const char *data, long count) {
    try {
      restart_values(format, data, count);
    } catch (const InputError &e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(refusal(wall, bytes, 3),
            "the restart file's state for fix wall/stress holds 4 values where this command needs 3");
  EXPECT_EQ(refusal(RestartFormat{RestartStyle::WallStress, 2, "fix wall/stress"}, bytes, 4),
            "the restart file's state for fix wall/stress has format version 1, this build reads "
            "version 2");
  EXPECT_EQ(refusal(RestartFormat{RestartStyle::Darcy, 1, "fix darcy/pressure"}, bytes, -1),
            "the restart file's state for fix darcy/pressure was not written by this style of this "
            "package");
  const std::vector<double> foreign = {2.0, 1.0, 1.0, 4.0, 0, 0, 0, 0};    // an older layout
  EXPECT_NE(refusal(wall, (const char *) foreign.data(), 4), "");
  // a style that also reads older versions: those read back with their version, others not
  const RestartFormat wall_2{RestartStyle::WallStress, 3, "fix wall/stress", 2};
  EXPECT_EQ(refusal(wall_2, bytes, 4),
            "the restart file's state for fix wall/stress has format version 1, this build reads "
            "version 2 to 3");
  const std::vector<double> block_2 =
      restart_block(RestartFormat{RestartStyle::WallStress, 2, "fix wall/stress"}, values);
  int version = 0;
  EXPECT_EQ(restart_values(wall_2, (const char *) block_2.data(), 4, &version), values);
  EXPECT_EQ(version, 2);
}

namespace {
// a fluid of a 2 x 2 x 3 grid with the given `seepage` value
std::unique_ptr<DarcyFluid> seepage_fluid(const char *seepage)
{
  KeywordReader in("fix darcy/pressure",
                   std::vector<std::string>{"grid", "2", "2", "3", "viscosity", "1",
                                            "compressibility", "1", "density", "1", "permeability",
                                            "1", "seepage", seepage});
  return std::unique_ptr<DarcyFluid>(new DarcyFluid(
      parse_darcy(in, 0.0, 1.0), GridGeom{0, 0, 0, 0.5, 0.5, 1.0 / 3.0, 2, 2, 3}, "f"));
}
}    // namespace

TEST(DarcyFluid, RestartRecordsTheSeepageAndAContinuationWithTheOtherIsRefused)
{
  const std::vector<double> full = seepage_fluid("full")->restart_state(),
                            pressure = seepage_fluid("pressure")->restart_state();
  auto refusal = [](const char *seepage, const std::vector<double> &state, int version) {
    try {
      seepage_fluid(seepage)->restore(state, version);
    } catch (const InputError &e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(refusal("full", full, 4), "");
  EXPECT_EQ(refusal("pressure", pressure, 4), "");
  EXPECT_EQ(refusal("pressure", full, 4),
            "fix darcy/pressure: the restart file's run had seepage full, this command has "
            "seepage pressure: continue with the force the run started with, or start a new run");
  EXPECT_EQ(refusal("full", pressure, 4),
            "fix darcy/pressure: the restart file's run had seepage pressure, this command has "
            "seepage full: continue with the force the run started with, or start a new run");
  // a state of format version 3 (written before the keyword: without its value) was a run
  // with seepage pressure
  std::vector<double> version_3 = pressure;
  version_3.erase(version_3.begin() + 13);
  EXPECT_EQ(refusal("pressure", version_3, 3), "");
  EXPECT_NE(refusal("full", version_3, 3).find("had seepage pressure, this command has seepage full"),
            std::string::npos);
  EXPECT_EQ(DarcyFluid::RESTART.version, 4);
  EXPECT_EQ(DarcyFluid::RESTART.oldest_version, 3);
}

TEST(DarcyFluid, MemoryIsWhatItHoldsAndATooLargeGridStopsBeforeAllocating)
{
  KeywordReader in("fix darcy/pressure",
                   std::vector<std::string>{"grid", "4", "3", "5", "viscosity", "1",
                                            "compressibility", "1", "density", "1", "permeability",
                                            "1"});
  const DarcySettings s = parse_darcy(in, 0.0, 1.0);
  const GridGeom geom{0, 0, 0, 0.25, 1.0 / 3.0, 0.2, 4, 3, 5};
  const DarcyFluid fluid(s, geom, "f");
  EXPECT_EQ(fluid.bytes(), DarcyFluid::bytes_for(geom));
  EXPECT_EQ(fluid.solver().bytes(), DarcySolver::bytes_for(geom));
  DarcySettings huge = s;
  huge.grid[0] = huge.grid[1] = huge.grid[2] = 4000;
  const GridGeom huge_geom{0, 0, 0, 1, 1, 1, 4000, 4000, 4000};
  try {
    DarcyFluid too_large(huge, huge_geom, "f");
    ADD_FAILURE() << "a 4000^3 grid was accepted";
  } catch (const InputError &e) {
    EXPECT_NE(std::string(e.what()).find("grid 4000x4000x4000 has 6.4e+10 cells"), std::string::npos)
        << e.what();
  }
  // 300 x 300 x 500 cells index within an int but need ~3.7e10 bytes: refused on a machine
  // with less memory (constructed nowhere else, so as not to allocate it)
  huge.grid[0] = huge.grid[1] = 300;
  huge.grid[2] = 500;
  const GridGeom big_geom{0, 0, 0, 1, 1, 1, 300, 300, 500};
  if (DarcyFluid::bytes_for(big_geom) > DarcyFluid::machine_memory()) {
    try {
      DarcyFluid too_large(huge, big_geom, "f");
      ADD_FAILURE() << "a grid larger than the memory was accepted";
    } catch (const InputError &e) {
      EXPECT_NE(std::string(e.what()).find("bytes, more than this machine's"), std::string::npos)
          << e.what();
    }
  }
}

TEST(Formula, TheFirstTermThatReadsPerAtomDataIsNamed)
{
  std::map<std::string, std::string> variables = {
      {"zwall", "f_wall[1]"}, {"mid", "xcm(all,z)+1"}, {"deep", "v_mid*2"}, {"t2", "time*time"}};
  auto of = [&variables](const std::string &name) {
    const auto it = variables.find(name);
    return it == variables.end() ? std::string() : it->second;
  };
  // time, step, numbers (an exponent is not a name), math functions, the box, fixes' values
  for (const char *none : {"8.0e4+7.0e4*sin(2*PI*0.4*time)", "v_zwall", "v_t2+step*dt",
                           "1e5*lx*ly", "f_wall[3]+f_fl[1]", "exp(-2.5e-3*elapsed)", "ramp(0,1)"})
    EXPECT_EQ(atom_data_read_by(none, of), "") << none;
  EXPECT_EQ(atom_data_read_by("1+xcm(all,z)", of), "xcm(), a group function");
  EXPECT_EQ(atom_data_read_by("2*x[12]", of), "x[], a per-atom value");
  EXPECT_EQ(atom_data_read_by("c_thermo_press/3", of), "c_thermo_press, a compute");
  EXPECT_EQ(atom_data_read_by("pe+1", of), "pe, a thermo keyword over the atoms");
  EXPECT_EQ(atom_data_read_by("v_deep", of), "xcm(), a group function in variable mid in variable deep");
  EXPECT_EQ(atom_data_read_by("v_nowhere", of), "");    // an unknown formula names nothing
  // a name that only contains a keyword is not it
  EXPECT_EQ(atom_data_read_by("v_temperature+v_pressure", of), "");
}
