#pragma once

#include <stdexcept>
#include <string>

namespace DuctileContact
{
  /**
   * An error the user can fix by editing the input: it names the .prm entry,
   * the offending value and what is allowed. The application catches it on
   * every rank, prints the message once (rank 0) and exits with a non-zero
   * code before any computation has started.
   */
  class InputError : public std::runtime_error
  {
  public:
    InputError(const std::string &entry,
               const std::string &value,
               const std::string &allowed);

    /// For errors that are not about a single entry (e.g. a mesh file).
    explicit InputError(const std::string &message);
  };

  /// Throws InputError(entry, value, allowed) unless @p condition holds.
  inline void
  check_input(const bool         condition,
              const std::string &entry,
              const std::string &value,
              const std::string &allowed)
  {
    if (!condition)
      throw InputError(entry, value, allowed);
  }
} // namespace DuctileContact
