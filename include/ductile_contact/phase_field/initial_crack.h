#pragma once

#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <ductile_contact/discretisation/discretisation.h>
#include <ductile_contact/materials/body_parameters.h>

#include <deque>

namespace DuctileContact
{
  /**
   * An initial crack as data: s = min(1, max(0, f_k(X))) at the nodes of s
   * of each body k with `Fracture/Initial crack` f_k, an expression of the
   * reference coordinates X = (x, y, z) (BodyParameters::check() has parsed
   * it). Sets the entries of @p u this rank owns; the other entries of u
   * stay as they are; returns whether any body has an initial crack (then
   * Simulation relaxes it at zero load before the first step).
   */
  bool
  set_initial_crack(const Discretisation                       &discretisation,
                    const std::deque<BodyParameters>           &bodies,
                    dealii::TrilinosWrappers::MPI::BlockVector &u);
} // namespace DuctileContact
