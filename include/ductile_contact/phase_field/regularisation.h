#pragma once

#include <ductile_contact/core/option.h>

namespace DuctileContact
{
  /**
   * Fracture/Regularisation: the crack density gamma of the phase field
   * (doc/model.md section 4):
   *  - fourth order (the paper's (3)): gamma = s^2/(4 l_f)
   *    + l_f/2 |grad s|^2 + l_f^3/4 (Lap s)^2, by C0IP with interior-face
   *    terms;
   *  - second order (AT2, Miehe et al. 2010): gamma = s^2/(2 l_f)
   *    + l_f/2 |grad s|^2, an H^1 form without face terms; its l_f is
   *    Miehe's l (twice the fourth-order l_f for the same transition zone).
   */
  enum class Regularisation
  {
    fourth_order,
    second_order
  };

  /**
   * Fracture/Energy split: which part of the elastic energy of an elastic
   * body degrades and drives the crack (doc/model.md (17), (27)):
   *  - volumetric-deviatoric: the deviatoric energy always, the volumetric
   *    one only in expansion (J > 1), so a crack cannot interpenetrate;
   *  - none: the whole energy, in compression too (the model of codes
   *    without a split, e.g. pfm-cracks' notched tension);
   *  - spectral: the energy of the positive principal strains and of a
   *    positive trace (Miehe et al. 2010; Elastic law = linear only, see
   *    degraded_linear_elasticity()).
   */
  enum class EnergySplit
  {
    volumetric_deviatoric,
    none,
    spectral
  };

  inline const NameTable<EnergySplit> &
  energy_split_names()
  {
    static const NameTable<EnergySplit> t{{EnergySplit::volumetric_deviatoric,
                                           "volumetric-deviatoric"},
                                          {EnergySplit::none, "none"},
                                          {EnergySplit::spectral, "spectral"}};
    return t;
  }

  inline const NameTable<Regularisation> &
  regularisation_names()
  {
    static const NameTable<Regularisation> t{
      {Regularisation::fourth_order, "fourth order"},
      {Regularisation::second_order, "second order"}};
    return t;
  }
} // namespace DuctileContact
