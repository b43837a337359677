#pragma once

#include <ductile_contact/contact/quad9.h>

#include <array>
#include <memory>

namespace DuctileContact
{
  /// Number of derivative directions of a face pair: the current
  /// coordinates of the 9 slave nodes (3 i + c) and of the 9 master nodes
  /// (27 + 3 i + c).
  constexpr unsigned int face_pair_coordinates = 54;

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
  /// their derivatives with respect to the 54 face coordinates.
  struct FacePairOperators
  {
    /// D_ik = int Phi_i N_k dA, M_il = int Phi_i (N_l o chi) dA over the
    /// overlap (i, k slave nodes, l master nodes) [m^2]; D as SlaveWeights
    /// says.
    std::array<std::array<double, 9>, 9> D, M;
    /// dD_ik / dX_a and dM_il / dX_a [m].
    std::array<std::array<std::array<double, face_pair_coordinates>, 9>, 9> dD,
      dM;
  };

  /**
   * The multiplier basis Phi_i = sum_k a_ik N_k of one slave quad9 face and
   * its mortar operators with any master face (mortar_points()).
   *
   * Dual (biorthogonal) basis (Wohlmuth 2000): int Phi_i N_k dA = delta_ik
   * int N_k dA over the face, i.e. a = D_e M_e^-1 with the face's mass
   * matrix M_e and D_e = diag(int N_i dA) (positive for quad9, so no basis
   * transformation is needed); sum_i Phi_i = 1, so uniform pressures are
   * still represented exactly. Standard basis: a = I.
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
    MortarFace(const Quad9       &slave,
               const bool         dual,
               const SlaveWeights weights = SlaveWeights::full);

    /// Operators of this face with @p master; false when the faces do not
    /// overlap (then @p out is not touched).
    bool
    integrate(const Quad9       &master,
              FacePairOperators &out,
              const bool         derivatives) const;

  private:
    /// The basis coefficients a_ik with their derivatives (ContactAD).
    struct BasisDerivatives;

    Quad9                                slave;
    bool                                 dual;
    SlaveWeights                         weights;
    std::array<std::array<double, 9>, 9> coefficients;
    /// Made by the first integrate() with derivatives and kept for the
    /// face's other pairs: they depend on the slave face alone.
    mutable std::shared_ptr<const BasisDerivatives> basis_derivatives;
  };
} // namespace DuctileContact
