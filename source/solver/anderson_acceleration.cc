#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <ductile_contact/solver/anderson_acceleration.h>

namespace DuctileContact
{
  using namespace dealii;

  AndersonAcceleration::AndersonAcceleration(const unsigned int depth)
      : depth(depth)
  {
  }



  void
  AndersonAcceleration::reset()
  {
    residual_differences.clear();
    image_differences.clear();
    has_last = false;
  }



  void
  AndersonAcceleration::update(const TrilinosWrappers::MPI::Vector &x,
                               TrilinosWrappers::MPI::Vector       &image)
  {
    if (depth == 0)
      return;
    TrilinosWrappers::MPI::Vector residual = image;
    residual -= x;
    if (has_last)
      {
        residual_differences.push_back(residual);
        residual_differences.back() -= last_residual;
        image_differences.push_back(image);
        image_differences.back() -= last_image;
        if (residual_differences.size() > depth)
          {
            residual_differences.pop_front();
            image_differences.pop_front();
          }
      }
    last_residual = residual;
    last_image    = image;
    has_last      = true;

    const unsigned int m = residual_differences.size();
    if (m == 0)
      return;
    LAPACKFullMatrix<double> gram(m, m);
    Vector<double>           rhs(m), gamma(m);
    for (unsigned int i = 0; i < m; ++i)
      {
        rhs(i) = residual_differences[i] * residual;
        for (unsigned int j = 0; j <= i; ++j)
          gram(i, j) = gram(j, i) =
            residual_differences[i] * residual_differences[j];
      }
    gram.compute_inverse_svd(1e-12);
    gram.vmult(gamma, rhs);
    for (unsigned int i = 0; i < m; ++i)
      image.add(-gamma(i), image_differences[i]);
  }
} // namespace DuctileContact
