// The pieces of the consistent contact tangent against central
// finite differences (relative to the largest derivative, step 1e-6 of
// the face size):
//  - dD and dM of a face pair (MortarFace): a curved, distorted slave
//    quad9 face and a rotated, shifted, curved master face that overlaps
//    it partly (polygon vertices from both faces and from edge
//    intersections), dual and standard multiplier basis, and the same
//    faces flat and touching (zero gap, as at the start of a patch test);
//  - lumped slave weights (SlaveWeights::lumped, semi-smooth Newton): D_ii
//    and its derivatives are the row sums of the full D, the rest of D is
//    zero and M is unchanged, with and without derivatives;
//  - the derivatives of a face's unit normal (Quad9::normal_derivatives);
//  - the Jacobian of the nodal contact law (nodal_contact) when the node
//    sticks, when it slips (with a rotated traction history) and without
//    friction.
#include <deal.II/base/mpi.h>

#include <ductile_contact/contact/mortar_operators.h>
#include <ductile_contact/contact/nodal_contact.h>

#include "tests.h"

#include <cmath>

using namespace dealii;
using namespace DuctileContact;

namespace
{
  /// A face over the parameter square, mapped to (size s) and curved /
  /// twisted; @p down swaps the parameters (normal along -z).
  Quad9
  face(const double z,
       const bool   down,
       const double angle,
       const double dx,
       const double dy,
       const double bulge)
  {
    Quad9 q;
    for (unsigned int i = 0; i < 9; ++i)
      {
        const Point<2> xi = Quad9::node_parameter(i);
        const double   u = down ? xi[1] : xi[0], v = down ? xi[0] : xi[1];
        // distorted parameter square, then rotated and shifted
        const double x = u - 0.5 + 0.07 * u * v, y = v - 0.5 - 0.05 * u * u;
        q.x[i] = Point<dim>(dx + std::cos(angle) * x - std::sin(angle) * y,
                            dy + std::sin(angle) * x + std::cos(angle) * y,
                            z + bulge * (u * (1 - u) + 0.5 * v * (1 - v) +
                                         0.4 * u * v));
      }
    return q;
  }

  /// Largest |analytic - finite difference| over the largest |analytic|.
  struct Error
  {
    double difference = 0., scale = 0.;
    void
    add(const double analytic, const double fd)
    {
      difference = std::max(difference, std::abs(analytic - fd));
      scale      = std::max(scale, std::abs(analytic));
    }
    double
    relative() const
    {
      return difference / scale;
    }
  };

  void
  check_operators(std::ostream &out, const bool dual, const bool flat)
  {
    const Quad9 slave = face(0., false, 0., 0., 0., flat ? 0. : 0.08);
    const Quad9 master =
      face(flat ? 0. : 2e-3, true, 0.4, 0.35, 0.2, flat ? 0. : -0.05);
    FacePairOperators exact, plus, minus;
    MortarFace(slave, dual).integrate(master, exact, true);
    FacePairOperators values;
    MortarFace(slave, dual).integrate(master, values, false);
    Error        dD, dM;
    double       value_difference = 0.;
    const double h                = 1e-6;
    for (unsigned int i = 0; i < 9; ++i)
      for (unsigned int k = 0; k < 9; ++k)
        value_difference = std::max({value_difference,
                                     std::abs(values.D[i][k] - exact.D[i][k]),
                                     std::abs(values.M[i][k] - exact.M[i][k])});
    for (unsigned int a = 0; a < face_pair_coordinates; ++a)
      {
        Quad9 s_plus = slave, s_minus = slave, m_plus = master,
              m_minus = master;
        if (a < 27)
          {
            s_plus.x[a / 3][a % 3] += h;
            s_minus.x[a / 3][a % 3] -= h;
          }
        else
          {
            m_plus.x[(a - 27) / 3][a % 3] += h;
            m_minus.x[(a - 27) / 3][a % 3] -= h;
          }
        MortarFace(s_plus, dual).integrate(m_plus, plus, false);
        MortarFace(s_minus, dual).integrate(m_minus, minus, false);
        for (unsigned int i = 0; i < 9; ++i)
          for (unsigned int k = 0; k < 9; ++k)
            {
              dD.add(exact.dD[i][k][a],
                     (plus.D[i][k] - minus.D[i][k]) / (2 * h));
              dM.add(exact.dM[i][k][a],
                     (plus.M[i][k] - minus.M[i][k]) / (2 * h));
            }
      }
    const std::string name =
      std::string(dual ? "dual basis" : "standard basis") +
      (flat ? ", flat touching faces" : "");
    std::cout << name << ": dD " << dD.relative() << " dM " << dM.relative()
              << " values " << value_difference << std::endl;
    out << name << ": values with and without derivatives agree (1e-14): "
        << Testing::yes_no(value_difference < 1e-14)
        << ", dD and dM match finite differences (1e-7): "
        << Testing::yes_no(dD.relative() < 1e-7 && dM.relative() < 1e-7)
        << std::endl;
  }

  void
  check_lumped(std::ostream &out, const bool derivatives)
  {
    const Quad9       slave  = face(0., false, 0., 0., 0., 0.08);
    const Quad9       master = face(2e-3, true, 0.4, 0.35, 0.2, -0.05);
    FacePairOperators full, lumped;
    MortarFace(slave, true).integrate(master, full, derivatives);
    MortarFace(slave, true, SlaveWeights::lumped)
      .integrate(master, lumped, derivatives);
    const unsigned int n_a = derivatives ? face_pair_coordinates : 0;
    Error              sums, rest, m;
    for (unsigned int i = 0; i < 9; ++i)
      {
        double                                    sum = 0.;
        std::array<double, face_pair_coordinates> dsum{};
        for (unsigned int k = 0; k < 9; ++k)
          {
            sum += full.D[i][k];
            for (unsigned int a = 0; a < n_a; ++a)
              dsum[a] += full.dD[i][k][a];
            if (k != i)
              rest.add(0., std::abs(lumped.D[i][k]));
            m.add(full.M[i][k], lumped.M[i][k]);
            for (unsigned int a = 0; a < n_a; ++a)
              {
                if (k != i)
                  rest.add(0., std::abs(lumped.dD[i][k][a]));
                m.add(full.dM[i][k][a], lumped.dM[i][k][a]);
              }
          }
        sums.add(sum, lumped.D[i][i]);
        for (unsigned int a = 0; a < n_a; ++a)
          sums.add(dsum[a], lumped.dD[i][i][a]);
      }
    std::cout << "lumped" << (derivatives ? " with derivatives" : "")
              << ": sums " << sums.relative() << " rest " << rest.difference
              << " M " << m.relative() << std::endl;
    out << "lumped slave weights" << (derivatives ? ", derivatives" : "")
        << ": D_ii = sum_k D_ik (1e-12): "
        << Testing::yes_no(sums.relative() < 1e-12)
        << ", the rest of D zero: " << Testing::yes_no(rest.difference == 0.)
        << ", M unchanged (1e-12): " << Testing::yes_no(m.relative() < 1e-12)
        << std::endl;
  }

  void
  check_normal(std::ostream &out)
  {
    const Quad9  q = face(0., false, 0.3, 0.1, 0.2, 0.2);
    Error        e;
    const double h = 1e-6;
    for (const Point<2> xi :
         {Point<2>(0., 0.), Point<2>(0.5, 1.), Point<2>(0.3, 0.6)})
      {
        const auto dn = q.normal_derivatives(xi);
        for (unsigned int i = 0; i < 9; ++i)
          for (unsigned int m = 0; m < dim; ++m)
            {
              Quad9 p = q, n = q;
              p.x[i][m] += h;
              n.x[i][m] -= h;
              const Tensor<1, dim> fd = (p.normal(xi) - n.normal(xi)) / (2 * h);
              for (unsigned int c = 0; c < dim; ++c)
                e.add(dn[i][c][m], fd[c]);
            }
      }
    std::cout << "normal " << e.relative() << std::endl;
    out << "face normal derivatives match finite differences (1e-8): "
        << Testing::yes_no(e.relative() < 1e-8) << std::endl;
  }

  void
  check_law(std::ostream      &out,
            const std::string &name,
            const double       friction,
            const double       tangential_penalty,
            const unsigned int expected_state)
  {
    NodalAggregates a;
    a.area   = 0.04;
    a.G      = Tensor<1, dim>({0.3e-5, -0.2e-5, -1.5e-5});
    a.H      = Tensor<1, dim>({2e-6, 1e-6, 0.3e-6});
    a.normal = Tensor<1, dim>({0.1, -0.2, 1.});
    a.normal /= a.normal.norm();
    NodalContactParameters p;
    p.penalty            = 1e10;
    p.tangential_penalty = tangential_penalty;
    p.friction           = friction;
    // an accepted traction that is not in the current tangent plane
    const Tensor<1, dim>    committed({1e5, 2e5, 0.5e5});
    const double            multiplier = 1e6;
    const NodalContactState state = nodal_contact(a, multiplier, committed, p);
    Error                   e;
    for (unsigned int d = 0; d < 10; ++d)
      {
        NodalAggregates plus = a, minus = a;
        double         &vp = d == 0  ? plus.area
                             : d < 4 ? plus.G[d - 1]
                             : d < 7 ? plus.H[d - 4]
                                     : plus.normal[d - 7];
        double         &vm = d == 0  ? minus.area
                             : d < 4 ? minus.G[d - 1]
                             : d < 7 ? minus.H[d - 4]
                                     : minus.normal[d - 7];
        const double    h  = 1e-7 * std::max(std::abs(vp), 1e-5);
        vp += h;
        vm -= h;
        const Tensor<1, dim> fd =
          (nodal_contact(plus, multiplier, committed, p).force_density -
           nodal_contact(minus, multiplier, committed, p).force_density) /
          (2 * h);
        for (unsigned int c = 0; c < dim; ++c)
          e.add(state.jacobian[c][d], fd[c]);
      }
    std::cout << name << " " << e.relative() << " state "
              << int(state.friction_state) << std::endl;
    out << "nodal law, " << name << ": state as expected: "
        << Testing::yes_no(state.active &&
                           state.friction_state == expected_state)
        << ", Jacobian matches finite differences (1e-7): "
        << Testing::yes_no(e.relative() < 1e-7) << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ofstream                    out = Testing::open_output();
  check_operators(out, true, false);
  check_operators(out, false, false);
  check_operators(out, true, true);
  check_lumped(out, false);
  check_lumped(out, true);
  check_normal(out);
  check_law(out, "no friction", 0., 1e10, 0);
  check_law(out, "stick", 10., 1e10, 1);
  check_law(out, "slip", 0.05, 1e10, 2);
}
