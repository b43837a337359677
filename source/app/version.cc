#include <deal.II/base/config.h>

#include <ductile_contact/app/version.h>

// Written by cmake/revision.cmake at every build: DUCTILE_CONTACT_REVISION,
// DUCTILE_CONTACT_VERSION and DUCTILE_CONTACT_BUILD_TYPE.
#include "revision.h"

namespace DuctileContact
{
  std::string
  source_revision()
  {
    return DUCTILE_CONTACT_REVISION;
  }



  std::string
  version_line()
  {
    return std::string("ductile-contact ") + DUCTILE_CONTACT_VERSION +
           ", revision " + source_revision() + ", deal.II " +
           DEAL_II_PACKAGE_VERSION + ", " + DUCTILE_CONTACT_BUILD_TYPE;
  }
} // namespace DuctileContact
