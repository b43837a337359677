#include <deal.II/base/mpi.h>

#include <ductile_contact/app/stop_request.h>

#include <csignal>

namespace DuctileContact
{
  namespace
  {
    volatile std::sig_atomic_t received = 0;

    extern "C" void
    note_stop_signal(const int signal)
    {
      received = 1;
      // The next one of this kind takes the default action (ends the run).
      std::signal(signal, SIG_DFL);
    }
  } // namespace



  void
  install_stop_handlers()
  {
    std::signal(SIGTERM, note_stop_signal);
    std::signal(SIGINT, note_stop_signal);
  }



  bool
  stop_requested(const MPI_Comm comm)
  {
    return dealii::Utilities::MPI::max(static_cast<int>(received), comm) > 0;
  }
} // namespace DuctileContact
