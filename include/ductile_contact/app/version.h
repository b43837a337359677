#pragma once

#include <string>

namespace DuctileContact
{
  /**
   * What this build is: the project version, the git revision of the
   * sources it was built from (with "-dirty" when they had uncommitted
   * changes; "unknown" outside a git checkout), the deal.II version and the
   * build type, on one line:
   *
   *   ductile-contact 0.3.0, revision 1a2b3c4, deal.II 9.4.1, Release
   *
   * Printed by --version, written at the top of log.txt and into every
   * checkpoint.
   */
  std::string
  version_line();

  /// The git revision alone.
  std::string
  source_revision();
} // namespace DuctileContact
