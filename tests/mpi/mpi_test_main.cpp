// doctest's main() for tests run under mpirun: MPI around the test run, full output from rank 0
// and failures only from the others, and a failure on any rank fails every rank. Compiled with
// DPGEN_TEST_WITH_PETSC, PETSc is initialized around the tests too.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <mpi.h>
#ifdef DPGEN_TEST_WITH_PETSC
#include "dpgen/petsc/linear_solver.hpp"
#endif

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  int failed = 0;
  {
#ifdef DPGEN_TEST_WITH_PETSC
    dpgen::petsc::Session petsc;
#endif
    doctest::Context context(argc, argv);
    if (rank != 0)
      context.setOption("minimal", true);
    failed = context.run() != 0 ? 1 : 0;
  }
  int any = 0;
  MPI_Allreduce(&failed, &any, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
  return any;
}
