#pragma once

#include <ductile_contact/contact/contact_face.h>

#include <array>
#include <memory>

namespace DuctileContact
{
  /// Which slave weights a face pair's D holds.
  enum class SlaveWeights
  {
    /// D_ik for every slave node pair.
    full,
    /// The row sums only: D_ii holds sum_k D_ik = int Phi_i dA (over the
    /// overlap) and the other entries are zero. This is all that D lumped
    /// to its row's node needs (the semi-smooth Newton enforcement,
    /// contact_problem.h), at a fraction of the cost.
    lumped
  };

  /// The mortar operators of one slave/master face pair and, on request,
  /// their derivatives with respect to the face pair's coordinates
  /// (face_pair_coordinates: 54 | 12).
  struct FacePairOperators
  {
    /// D_ik = int Phi_i N_k dA, M_il = int Phi_i (N_l o chi) dA over the
    /// overlap (i, k slave nodes, l master nodes) [m^2]; D as SlaveWeights
    /// says.
    std::array<std::array<double, face_nodes>, face_nodes> D, M;
    /// dD_ik / dX_a and dM_il / dX_a [m].
    std::array<
      std::array<std::array<double, face_pair_coordinates>, face_nodes>,
      face_nodes>
      dD, dM;
  };

  /**
   * The multiplier basis Phi_i = sum_k a_ik N_k of one slave face and
   * its mortar operators with any master face (mortar_points()).
   *
   * Dual (biorthogonal) basis (Wohlmuth 2000): int Phi_i N_k dA = delta_ik
   * int N_k dA over the face, i.e. a = D_e M_e^-1 with the face's mass
   * matrix M_e and D_e = diag(int N_i dA) (positive for quad9 and for every
   * valid line3: (4 beta - 1) L/6, 2L/3, (3 - 4 beta) L/6 with the middle
   * node at beta of the chord L, so no basis transformation is needed); sum_i
   * Phi_i = 1, so uniform pressures are still represented exactly. Standard
   * basis: a = I.
   *
   * The operators are accumulated as D = a Dhat, M = a Mhat with Dhat_mk =
   * int N_m N_k, Mhat_ml = int N_m (N_l o chi): the basis is applied once
   * per pair instead of at every integration point. With derivatives the
   * whole computation (basis coefficients included, they depend on the
   * slave face's shape) runs in ContactAD: that is the consistent
   * linearisation of D and M (contact_problem.h). The coefficients in
   * ContactAD are made once per MortarFace, for all its master faces. With
   * lumped weights the sums over the points are two matrix products of the
   * points' derivatives by the chain rule instead (doc/contact.md section
   * 7, "dD, dM").
   */
  class MortarFace
  {
  public:
    MortarFace(const ContactFace &slave,
               const bool         dual,
               const SlaveWeights weights = SlaveWeights::full);

    /// Operators of this face with @p master; false when the faces do not
    /// overlap (then @p out is not touched).
    bool
    integrate(const ContactFace &master,
              FacePairOperators &out,
              const bool         derivatives) const;

  private:
    /// The basis coefficients a_ik with their derivatives (ContactAD).
    struct BasisDerivatives;

    ContactFace                                            slave;
    bool                                                   dual;
    SlaveWeights                                           weights;
    std::array<std::array<double, face_nodes>, face_nodes> coefficients;
    /// Made by the first integrate() with derivatives and kept for the
    /// face's other pairs: they depend on the slave face alone.
    mutable std::shared_ptr<const BasisDerivatives> basis_derivatives;
  };
} // namespace DuctileContact
