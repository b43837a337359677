#include <deal.II/base/mpi.h>

#include <ductile_contact/app/application.h>
#include <ductile_contact/app/command_line.h>

#include <cerrno>
#include <cstring>
#include <exception>
#include <iostream>
#include <unistd.h>

int
main(int argc, char **argv)
{
  // An input of the other dimension runs in the other build: the process
  // becomes that program, with the same arguments, before MPI starts.
  if (const auto program = DuctileContact::program_for_dimension(argc, argv))
    {
      execv(program->c_str(), argv);
      std::cerr << "Error: the input's Dimension needs the program '"
                << *program << "' (" << std::strerror(errno)
                << "); build and install it with the others" << std::endl;
      return 1;
    }
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
