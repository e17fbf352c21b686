// gtest main for tests that run LAMMPS: MPI and Kokkos are initialised once per process.
#include "library.h"

#include <gtest/gtest.h>
#include <mpi.h>

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  // only rank 0 reports, so an mpirun'd test prints one result
  if (me != 0) delete ::testing::UnitTest::GetInstance()->listeners().Release(
      ::testing::UnitTest::GetInstance()->listeners().default_result_printer());
  const int rc = RUN_ALL_TESTS();
  lammps_kokkos_finalize();
  MPI_Finalize();
  return rc;
}
