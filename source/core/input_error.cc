#include <ductile_contact/core/input_error.h>

namespace DuctileContact
{
  InputError::InputError(const std::string &entry,
                         const std::string &value,
                         const std::string &allowed)
      : std::runtime_error("entry '" + entry + "' has the value '" + value +
                           "', but " + allowed)
  {
  }

  InputError::InputError(const std::string &message)
      : std::runtime_error(message)
  {
  }
} // namespace DuctileContact
