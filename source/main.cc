#include <deal.II/base/mpi.h>

#include <ductile_contact/app/application.h>

#include <exception>
#include <iostream>

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      return DuctileContact::run_application(argc, argv, MPI_COMM_WORLD);
    }
  catch (const std::exception &e)
    {
      std::cerr << "Error: " << e.what() << std::endl;
      MPI_Abort(MPI_COMM_WORLD, 3);
    }
  return 3;
}
