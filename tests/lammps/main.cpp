// gtest main for tests that run LAMMPS: MPI and Kokkos are initialised once per process,
// and each process works in a directory of its own.
#include "library.h"

#include <gtest/gtest.h>
#include <mpi.h>

#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <stdexcept>
#include <string>

namespace {

// ctest -j runs the tests of one binary side by side in one directory, and the files the
// tests write (dumps, restarts, logs) have fixed names: each process (all ranks of an
// mpirun'd one together) gets a directory named after rank 0's pid
std::string enter_own_directory()
{
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  long pid = me == 0 ? static_cast<long>(getpid()) : 0;
  MPI_Bcast(&pid, 1, MPI_LONG, 0, MPI_COMM_WORLD);
  const std::string dir = "pwtest_process." + std::to_string(pid);
  if (me == 0 && mkdir(dir.c_str(), 0755) != 0)
    throw std::runtime_error("cannot make the test directory " + dir);
  MPI_Barrier(MPI_COMM_WORLD);
  if (chdir(dir.c_str()) != 0) throw std::runtime_error("cannot enter the test directory " + dir);
  return dir;
}

// the tests' files are plain files in that one directory
void remove_own_directory(const std::string &dir)
{
  if (chdir("..") != 0) return;
  if (DIR *d = opendir(dir.c_str())) {
    while (const dirent *e = readdir(d)) {
      const std::string name = e->d_name;
      if (name != "." && name != "..") std::remove((dir + "/" + name).c_str());
    }
    closedir(d);
  }
  rmdir(dir.c_str());
}

}    // namespace

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  // only rank 0 reports, so an mpirun'd test prints one result
  if (me != 0) delete ::testing::UnitTest::GetInstance()->listeners().Release(
      ::testing::UnitTest::GetInstance()->listeners().default_result_printer());
  const std::string dir = enter_own_directory();
  const int rc = RUN_ALL_TESTS();
  MPI_Barrier(MPI_COMM_WORLD);
  if (me == 0) remove_own_directory(dir);
  lammps_kokkos_finalize();
  MPI_Finalize();
  return rc;
}
