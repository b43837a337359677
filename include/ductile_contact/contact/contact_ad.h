#pragma once

#include <deal.II/base/config.h>

#include <ductile_contact/core/ad_value.h>

#include <Sacado.hpp>

namespace DuctileContact
{
  /**
   * Forward-mode automatic-differentiation number of the contact
   * linearisation: derivatives with respect to the 54 current coordinates
   * of one slave/master quad9 face pair, direction 3 i + c for slave node i
   * and 27 + 3 i + c for master node i (component c). A fixed size keeps
   * the numbers on the stack (the contact geometry works on plain arrays;
   * core/sacado_sfad.h would let deal.II's tensors take it).
   */
  using ContactAD = Sacado::Fad::SFad<double, 54>;
} // namespace DuctileContact
