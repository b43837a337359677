#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <ductile_contact/phase_field/operator_problems.h>

namespace DuctileContact
{
  using namespace dealii;

  namespace
  {
    /// s = cos(pi x) cos(pi y) cos(pi z) (without the z factor in 2-D)
    /// with derivatives.
    class CosineSolution : public Function<dim>
    {
    public:
      double
      value(const Point<dim> &p, const unsigned int = 0) const override
      {
        double v = 1.;
        for (unsigned int d = 0; d < dim; ++d)
          v *= std::cos(numbers::PI * p[d]);
        return v;
      }

      Tensor<1, dim>
      gradient(const Point<dim> &p, const unsigned int = 0) const override
      {
        Tensor<1, dim> g;
        for (unsigned int d = 0; d < dim; ++d)
          {
            g[d] = -numbers::PI;
            for (unsigned int e = 0; e < dim; ++e)
              g[d] *= (e == d) ? std::sin(numbers::PI * p[e])
                               : std::cos(numbers::PI * p[e]);
          }
        return g;
      }

      SymmetricTensor<2, dim>
      hessian(const Point<dim> &p, const unsigned int = 0) const override
      {
        SymmetricTensor<2, dim> H;
        const double            pi2 = numbers::PI * numbers::PI;
        for (unsigned int d = 0; d < dim; ++d)
          for (unsigned int e = d; e < dim; ++e)
            {
              double v = (d == e) ? -pi2 : pi2;
              for (unsigned int k = 0; k < dim; ++k)
                v *= (k == d || k == e) && d != e
                       ? std::sin(numbers::PI * p[k])
                       : std::cos(numbers::PI * p[k]);
              H[d][e] = v;
            }
        return H;
      }
    };



    /// A scalar FE_Q field with the C0IP operator on a distributed mesh.
    class ScalarC0IPSystem
    {
    public:
      ScalarC0IPSystem(parallel::distributed::Triangulation<dim> &tria,
                       const unsigned int                         degree)
          : fe(degree)
          , mapping(1)
          , dof_handler(tria)
          , quadrature(degree + 1)
          , face_quadrature(degree + 1)
      {
        dof_handler.distribute_dofs(fe);
        owned = dof_handler.locally_owned_dofs();
        DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
        constraints.reinit(relevant);
      }

      /// What the C0IP face terms need on an interface.
      FEInterfaceValues<dim>
      interface_values() const
      {
        return FEInterfaceValues<dim>(mapping,
                                      fe,
                                      face_quadrature,
                                      update_gradients | update_hessians |
                                        update_quadrature_points |
                                        update_normal_vectors |
                                        update_JxW_values);
      }

      /// After the constraints are final.
      void
      setup(const MPI_Comm comm)
      {
        constraints.close();
        DynamicSparsityPattern dsp(relevant);
        DoFTools::make_flux_sparsity_pattern(dof_handler,
                                             dsp,
                                             constraints,
                                             false);
        SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
        matrix.reinit(owned, owned, dsp, comm);
        rhs.reinit(owned, comm);
        solution.reinit(owned, relevant, comm);
      }

      /// Cell and face terms; @p cell_rhs(fe_values, cell_vector) adds
      /// load terms per cell.
      template <typename CellRhs>
      void
      assemble(const C0IPCoefficients &c, const CellRhs &cell_rhs)
      {
        const FEValuesExtractors::Scalar     s(0);
        FEValues<dim>                        fe_values(mapping,
                                fe,
                                quadrature,
                                update_values | update_gradients |
                                  update_hessians | update_quadrature_points |
                                  update_JxW_values);
        const unsigned int                   n = fe.n_dofs_per_cell();
        FullMatrix<double>                   cell_matrix(n, n);
        Vector<double>                       cell_vector(n);
        std::vector<types::global_dof_index> dofs(n);
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              fe_values.reinit(cell);
              cell_matrix = 0;
              cell_vector = 0;
              add_c0ip_cell_terms(fe_values, s, c, cell_matrix);
              cell_rhs(cell, fe_values, cell_vector);
              cell->get_dof_indices(dofs);
              constraints.distribute_local_to_global(
                cell_matrix, cell_vector, dofs, matrix, rhs);
            }

        FEInterfaceValues<dim> fiv = interface_values();
        FullMatrix<double>     face_matrix;
        Vector<double>         face_vector;
        for_each_interior_face(
          dof_handler,
          fiv,
          [&](const FEInterfaceValues<dim> &f, const double h_inv) {
            const unsigned int m = f.n_current_interface_dofs();
            face_matrix.reinit(m, m);
            face_vector.reinit(m);
            add_c0ip_face_terms(f, s, c, h_inv, face_matrix);
            // With a vector, inhomogeneous constraints (the strip's s = 1)
            // move their face-term contributions to the right-hand side.
            constraints.distribute_local_to_global(
              face_matrix,
              face_vector,
              f.get_interface_dof_indices(),
              matrix,
              rhs);
          });
        matrix.compress(VectorOperation::add);
        rhs.compress(VectorOperation::add);
      }

      void
      solve(const std::string &solver, OperatorSolveInfo &info)
      {
        TrilinosWrappers::MPI::Vector x(owned, matrix.get_mpi_communicator());
        if (solver == "direct")
          {
            SolverControl                  control(1, 0);
            TrilinosWrappers::SolverDirect direct(
              control,
              TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                             "Amesos_Mumps"));
            direct.solve(matrix, x, rhs);
            info.linear_iterations = 1;
          }
        else
          {
            TrilinosWrappers::PreconditionAMG::AdditionalData data;
            data.elliptic              = true;
            data.higher_order_elements = true;
            data.aggregation_threshold = 0.02;
            data.smoother_sweeps       = 2;
            TrilinosWrappers::PreconditionAMG amg;
            amg.initialize(matrix, data);
            SolverControl control(5000, 1e-12 * rhs.l2_norm());
            SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
            cg.solve(matrix, x, rhs, amg);
            info.linear_iterations = control.last_step();
          }
        constraints.distribute(x);
        solution = x;
      }

      /// a(s_h, s_h) with the C0IP form (cells and interior faces).
      double
      energy_form(const C0IPCoefficients &c) const
      {
        double              sum = 0;
        FEValues<dim>       fe_values(mapping,
                                fe,
                                quadrature,
                                update_values | update_gradients |
                                  update_hessians | update_JxW_values);
        std::vector<double> v(quadrature.size()), lap(quadrature.size());
        std::vector<Tensor<1, dim>> g(quadrature.size());
        std::vector<Tensor<2, dim>> H(quadrature.size());
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              fe_values.reinit(cell);
              fe_values.get_function_values(solution, v);
              fe_values.get_function_gradients(solution, g);
              fe_values.get_function_hessians(solution, H);
              for (unsigned int q = 0; q < v.size(); ++q)
                sum += (c.mass * v[q] * v[q] + c.gradient * g[q] * g[q] +
                        c.bilaplacian * trace(H[q]) * trace(H[q])) *
                       fe_values.JxW(q);
            }
        FEInterfaceValues<dim>           fiv = interface_values();
        const FEValuesExtractors::Scalar s(0);
        for_each_interior_face(
          dof_handler,
          fiv,
          [&](const FEInterfaceValues<dim> &f, const double h_inv) {
            const auto &dofs = f.get_interface_dof_indices();
            for (unsigned int q = 0; q < f.n_quadrature_points; ++q)
              {
                double jump = 0, mean_lap = 0;
                for (unsigned int i = 0; i < dofs.size(); ++i)
                  {
                    jump += solution(dofs[i]) *
                            (f[s].jump_in_gradients(i, q) * f.normal(q));
                    mean_lap +=
                      solution(dofs[i]) * trace(f[s].average_of_hessians(i, q));
                  }
                sum +=
                  c.bilaplacian *
                  (-2. * mean_lap * jump + c.penalty * h_inv * jump * jump) *
                  f.JxW(q);
              }
          });
        return Utilities::MPI::sum(sum, matrix.get_mpi_communicator());
      }

      FE_Q<dim>                      fe;
      MappingQ<dim>                  mapping;
      DoFHandler<dim>                dof_handler;
      QGauss<dim>                    quadrature;
      QGauss<dim - 1>                face_quadrature;
      IndexSet                       owned, relevant;
      AffineConstraints<double>      constraints;
      TrilinosWrappers::SparseMatrix matrix;
      TrilinosWrappers::MPI::Vector  rhs, solution;
    };
  } // namespace



  ManufacturedErrors
  solve_manufactured_c0ip(const unsigned int      degree,
                          const unsigned int      refinements,
                          const C0IPCoefficients &c,
                          const std::string      &solver,
                          const MPI_Comm          comm)
  {
    ManufacturedErrors                        result;
    Timer                                     timer(comm);
    parallel::distributed::Triangulation<dim> tria(comm);
    GridGenerator::hyper_cube(tria, 0., 1.);
    tria.refine_global(refinements);
    result.h = 1. / (1 << refinements);

    ScalarC0IPSystem system(tria, degree);
    system.setup(comm);
    result.info.n_dofs        = system.dof_handler.n_dofs();
    result.info.setup_seconds = timer.wall_time();

    const CosineSolution exact;
    const double         pi2 = numbers::PI * numbers::PI;
    // -Lap s = d pi^2 s, so L s = (mass + d pi^2 gradient + d^2 pi^4
    // bilaplacian) s in d dimensions.
    const double factor =
      c.mass + dim * pi2 * c.gradient + dim * dim * pi2 * pi2 * c.bilaplacian;
    FEFaceValues<dim> face_values(system.mapping,
                                  system.fe,
                                  system.face_quadrature,
                                  update_gradients | update_normal_vectors |
                                    update_quadrature_points |
                                    update_JxW_values);
    timer.restart();
    system.assemble(
      c, [&](const auto &cell, const FEValues<dim> &fv, Vector<double> &b) {
        for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
          {
            const double f = factor * exact.value(fv.quadrature_point(q));
            for (unsigned int i = 0; i < fv.dofs_per_cell; ++i)
              b(i) += f * fv.shape_value(i, q) * fv.JxW(q);
          }
        // Natural-condition data: int_dB bilaplacian Lap s d_n v dA.
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f))
            {
              face_values.reinit(cell, f);
              for (unsigned int q = 0; q < face_values.n_quadrature_points; ++q)
                {
                  const double lap_s =
                    trace(exact.hessian(face_values.quadrature_point(q)));
                  for (unsigned int i = 0; i < fv.dofs_per_cell; ++i)
                    b(i) += c.bilaplacian * lap_s *
                            (face_values.shape_grad(i, q) *
                             face_values.normal_vector(q)) *
                            face_values.JxW(q);
                }
            }
      });
    result.info.assembly_seconds = timer.wall_time();
    timer.restart();
    system.solve(solver, result.info);
    result.info.solve_seconds = timer.wall_time();

    const QGauss<dim> error_quadrature(degree + 2);
    const auto        global_error = [&](const VectorTools::NormType norm) {
      Vector<double> cellwise(tria.n_active_cells());
      VectorTools::integrate_difference(system.mapping,
                                        system.dof_handler,
                                        system.solution,
                                        exact,
                                        cellwise,
                                        error_quadrature,
                                        norm);
      return VectorTools::compute_global_error(tria, cellwise, norm);
    };
    result.l2 = global_error(VectorTools::L2_norm);
    result.h1 = global_error(VectorTools::H1_seminorm);

    FEValues<dim>               fe_values(system.mapping,
                            system.fe,
                            error_quadrature,
                            update_hessians | update_quadrature_points |
                              update_JxW_values);
    std::vector<Tensor<2, dim>> H(error_quadrature.size());
    double                      h2 = 0;
    for (const auto &cell : system.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values.get_function_hessians(system.solution, H);
          for (unsigned int q = 0; q < H.size(); ++q)
            h2 += (H[q] -
                   Tensor<2, dim>(exact.hessian(fe_values.quadrature_point(q))))
                    .norm_square() *
                  fe_values.JxW(q);
        }
    result.h2 = std::sqrt(Utilities::MPI::sum(h2, comm));
    return result;
  }



  StripResult
  solve_crack_strip(const unsigned int degree,
                    const double       half_length,
                    const unsigned int cells_per_lf,
                    const std::string &solver,
                    const MPI_Comm     comm)
  {
    StripResult                               result;
    Timer                                     timer(comm);
    const double                              h = 1. / cells_per_lf;
    parallel::distributed::Triangulation<dim> tria(comm);
    const unsigned int                        n_x =
      2 * static_cast<unsigned int>(std::lround(half_length * cells_per_lf));
    // Periodic in y and z: an infinite plate, so the exact minimiser is the
    // 1-D profile. (With natural conditions on the lateral faces, Lap s = 0
    // holds there weakly and the field bends across the bar to lower the
    // energy below Gamma(L): -19 % for a bar one cell of l_f/8 wide.)
    GridGenerator::subdivided_hyper_rectangle(tria,
                                              {n_x, 1, 1},
                                              Point<dim>(-half_length, 0, 0),
                                              Point<dim>(half_length, h, h),
                                              true);
    std::vector<GridTools::PeriodicFacePair<
      parallel::distributed::Triangulation<dim>::cell_iterator>>
      pairs;
    GridTools::collect_periodic_faces(tria, 2, 3, 1, pairs);
    GridTools::collect_periodic_faces(tria, 4, 5, 2, pairs);
    tria.add_periodicity(pairs);
    ScalarC0IPSystem system(tria, degree);
    DoFTools::make_periodicity_constraints(
      system.dof_handler, 2, 3, 1, system.constraints);
    DoFTools::make_periodicity_constraints(
      system.dof_handler, 4, 5, 2, system.constraints);

    // s = 1 on the crack plane x = 0 (an interior plane of vertices).
    std::vector<types::global_dof_index> face_dofs(system.fe.n_dofs_per_face());
    for (const auto &cell : system.dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int f : cell->face_indices())
          if (std::abs(cell->face(f)->center()[0]) < 1e-10 * h)
            {
              cell->face(f)->get_dof_indices(face_dofs);
              for (const auto i : face_dofs)
                if (system.relevant.is_element(i) &&
                    !system.constraints.is_constrained(i))
                  {
                    system.constraints.add_line(i);
                    system.constraints.set_inhomogeneity(i, 1.);
                  }
            }
    system.setup(comm);
    result.info.n_dofs        = system.dof_handler.n_dofs();
    result.info.setup_seconds = timer.wall_time();

    const C0IPCoefficients c =
      C0IPCoefficients::crack_functional(1., 1., degree);
    timer.restart();
    system.assemble(c,
                    [](const auto &, const FEValues<dim> &, Vector<double> &) {
                    });
    result.info.assembly_seconds = timer.wall_time();
    timer.restart();
    system.solve(solver, result.info);
    result.info.solve_seconds = timer.wall_time();

    // int gamma dV = a(s, s) / 2, per unit cross-section.
    result.gamma = 0.5 * system.energy_form(c) / (h * h);
    return result;
  }
} // namespace DuctileContact
