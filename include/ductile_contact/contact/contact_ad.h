#pragma once

#include <deal.II/base/config.h>

#include <ductile_contact/contact/contact_face.h>
#include <ductile_contact/core/ad_value.h>

#include <Sacado.hpp>

namespace DuctileContact
{
  /**
   * Forward-mode automatic-differentiation number of the contact
   * linearisation: derivatives with respect to the current coordinates of
   * one slave/master face pair (54 for quad9 faces, 12 for line3),
   * direction dim i + c for slave node i and face_coordinates + dim i + c
   * for master node i (component c; contact_face.h). A fixed size keeps
   * the numbers on the stack (the contact geometry works on plain arrays;
   * core/sacado_sfad.h would let deal.II's tensors take it).
   */
  using ContactAD = Sacado::Fad::SFad<double, face_pair_coordinates>;
} // namespace DuctileContact
