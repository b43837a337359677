#pragma once

#include <deal.II/base/parameter_handler.h>

#include <ostream>

namespace DuctileContact
{
  /**
   * Every entry of @p prm as a .prm file, in declaration order, each with
   * its documentation as a comment and "# default: ..." where its value
   * differs. deal.II 9.4's own PRM printer drops the subsections of a node
   * that is an entry too (`Body <id>/Plasticity` and `/Fracture` are both),
   * so this writes from the JSON tree instead, which keeps them.
   */
  void
  write_prm(const dealii::ParameterHandler &prm, std::ostream &out);
} // namespace DuctileContact
