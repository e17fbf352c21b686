// fix darcy/pressure's fields as LAMMPS per-grid data (LAMMPS since 22Dec2022; skipped on
// older hosts): dump grid and fix ave/grid hold the fix's own fields, cell for cell, also
// with the grid partitioned over MPI ranks (ctest runs the *Mpi* tests under mpirun -np 2, 3).
#include "darcy_inputs.h"
#include "lammps_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using pwtest::Lammps;

namespace {

bool is_rank0()
{
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  return me == 0;
}

const int CELLS = pwtest::bed_cells;    // 2 x 2 x 10

// the rows of the last snapshot of a text `dump grid` (written with sort id: grid ID order,
// x fastest, as the fix's flat fields), each row's columns
std::vector<std::vector<double>> last_grid_snapshot(const std::string &file)
{
  std::ifstream in(file);
  std::vector<std::vector<double>> rows;
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.rfind("ITEM:", 0) == 0) {
      if (line.rfind("ITEM: GRID CELLS", 0) == 0) {
        rows.clear();
        inside = true;
      } else {
        inside = false;
      }
      continue;
    }
    if (!inside) continue;
    std::istringstream words(line);
    std::vector<double> row;
    double v;
    while (words >> v) row.push_back(v);
    rows.push_back(row);
  }
  return rows;
}

// column `col` of the rows
std::vector<double> column(const std::vector<std::vector<double>> &rows, size_t col)
{
  std::vector<double> out;
  for (const auto &r : rows) out.push_back(r.at(col));
  return out;
}

// every `ncol`-th value of an interleaved field, starting at `c`
std::vector<double> component(const std::vector<double> &field, int ncol, int c)
{
  std::vector<double> out;
  for (size_t i = c; i < field.size(); i += ncol) out.push_back(field[i]);
  return out;
}

}    // namespace

TEST(FixDarcyGrid, DumpGridAndFixAveGridHoldTheFixFieldsMpi)
{
  PW_SKIP_BEFORE_LAMMPS(20221222, "Grid3d, dump grid or fix ave/grid");
  // the bed lifted by the fluid: pressure, porosity, permeability and the grains' mean
  // velocity all vary from cell to cell; fluid steps every 5 grain steps
  Lammps l;
  l.commands(pwtest::bed());
  l.command(pwtest::bed_fluid(pwtest::lifting_pressure, 5));
  l.commands("fix move mobile nve/sphere\n"
             "dump g all grid 10 pw_darcy_grid.txt f_fl:grid:pressure f_fl:grid:porosity "
             "f_fl:grid:permeability f_fl:grid:mean_velocity[1] f_fl:grid:mean_velocity[2] "
             "f_fl:grid:mean_velocity[3] f_fl:grid:pressure_gradient[3]\n"
             "dump_modify g sort id format float %.17g\n"
             "fix avg all ave/grid 5 1 10 2 2 10 f_fl:grid:pressure\n"
             "dump a all grid 10 pw_darcy_avegrid.txt f_avg:grid:data\n"
             "dump_modify a sort id format float %.17g\n");
  l.command("run 40");
  l.commands("undump g\nundump a\n");    // closes the files
  MPI_Barrier(MPI_COMM_WORLD);

  const auto dumped = last_grid_snapshot("pw_darcy_grid.txt");
  ASSERT_EQ(dumped.size(), (size_t) CELLS);
  const std::vector<double> pressure = l.fix_field("fl", "pressure", CELLS);
  const std::vector<double> porosity = l.fix_field("fl", "porosity", CELLS);
  const std::vector<double> velocity = l.fix_field("fl", "mean_velocity", 3 * CELLS);
  const std::vector<double> gradient = l.fix_field("fl", "pressure_gradient", 3 * CELLS);
  // copies of the fields, written with 17 digits: bit for bit
  EXPECT_EQ(column(dumped, 0), pressure);
  EXPECT_EQ(column(dumped, 1), porosity);
  EXPECT_EQ(column(dumped, 2), l.fix_field("fl", "permeability", CELLS));
  for (int d = 0; d < 3; ++d) EXPECT_EQ(column(dumped, 3 + d), component(velocity, 3, d)) << d;
  EXPECT_EQ(column(dumped, 6), component(gradient, 3, 2));
  // not a scene at rest: the fields vary over the cells
  EXPECT_GT(*std::max_element(pressure.begin(), pressure.end()), 0.1 * pwtest::lifting_pressure);
  EXPECT_LT(*std::min_element(porosity.begin(), porosity.end()),
            *std::max_element(porosity.begin(), porosity.end()));
  const auto vz = component(velocity, 3, 2);
  EXPECT_GT(*std::max_element(vz.begin(), vz.end()), 0.0);

  // fix ave/grid of one sample per output reads the same field
  const auto averaged = last_grid_snapshot("pw_darcy_avegrid.txt");
  ASSERT_EQ(averaged.size(), (size_t) CELLS);
  EXPECT_EQ(column(averaged, 0), pressure);
  MPI_Barrier(MPI_COMM_WORLD);    // every rank has read them
  if (is_rank0()) {
    std::remove("pw_darcy_grid.txt");
    std::remove("pw_darcy_avegrid.txt");
  }
}

TEST(FixDarcyGrid, OutputOffTheFluidStepsOrOfAnUnknownFieldIsRefused)
{
  PW_SKIP_BEFORE_LAMMPS(20221222, "Grid3d, dump grid or fix ave/grid");
  Lammps l;
  l.commands(pwtest::bed());
  l.command(pwtest::bed_fluid(pwtest::lifting_pressure, 5));
  // the fields change only on fluid steps: an output every 3 steps is refused
  pwtest::expect_error(l, "dump g all grid 3 pw_darcy_bad.txt f_fl:grid:pressure",
                       "fix fl not computed at compatible time");
  pwtest::expect_error(l, "dump g all grid 10 pw_darcy_bad.txt f_fl:grid:velocity",
                       "fix fl does not recognize data name velocity");
  pwtest::expect_error(l, "dump g all grid 10 pw_darcy_bad.txt f_fl:cells:pressure",
                       "fix fl does not recognize grid name cells");
  pwtest::expect_error(l, "dump g all grid 10 pw_darcy_bad.txt f_fl:grid:pressure[1]",
                       "fix fl data pressure is not per-grid array");
}
