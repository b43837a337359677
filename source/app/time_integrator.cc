#include <deal.II/base/function_parser.h>
#include <deal.II/dofs/dof_tools.h>

#include <ductile_contact/app/time_integrator.h>
#include <ductile_contact/core/expression.h>

#include <algorithm>
#include <map>
#include <memory>

namespace DuctileContact
{
  using namespace dealii;
  using BlockVector = TrilinosWrappers::MPI::BlockVector;

  TimeIntegrator::TimeIntegrator(
    const LoadSteppingParameters          &parameters,
    const std::deque<BodyParameters>      &bodies,
    const std::deque<BoundaryCondition>   &boundary_conditions,
    const Discretisation                  &discretisation,
    const std::vector<types::boundary_id> &massless_boundaries)
      : alpha_b((parameters.spectral_radius - 1.) /
                (parameters.spectral_radius + 1.))
      , beta(0.25 * (1. - alpha_b) * (1. - alpha_b))
      , gamma(0.5 - alpha_b)
      , bodies(bodies)
      , boundary_conditions(boundary_conditions)
      , discretisation(discretisation)
      , massless_boundaries(massless_boundaries)
  {
  }



  InertiaTerms &
  TimeIntegrator::reset_terms()
  {
    terms          = InertiaTerms();
    terms.massless = &massless;
    return terms;
  }



  void
  TimeIntegrator::setup()
  {
    const MPI_Comm comm = discretisation.dof_handler.get_communicator();
    for (BlockVector *v : {&velocity,
                           &acceleration,
                           &inertial_acceleration,
                           &new_velocity,
                           &new_acceleration,
                           &new_inertial_acceleration})
      v->reinit(discretisation.owned_partitioning, comm);
    for (BlockVector *v : {&target, &velocity_ghosted, &mean_acceleration})
      v->reinit(discretisation.owned_partitioning,
                discretisation.relevant_partitioning,
                comm);

    // The u DoFs of the massless faces of the owned and ghost cells: every
    // owned cell that touches such a node, by a face, an edge or a vertex,
    // finds it here.
    massless.clear();
    std::vector<types::global_dof_index> face_dofs;
    for (const auto &cell : discretisation.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() || cell->is_ghost())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              std::find(massless_boundaries.begin(),
                        massless_boundaries.end(),
                        cell->face(f)->boundary_id()) !=
                massless_boundaries.end())
            {
              const FiniteElement<dim> &fe = cell->get_fe();
              face_dofs.resize(fe.n_dofs_per_face(f));
              cell->face(f)->get_dof_indices(face_dofs,
                                             cell->active_fe_index());
              for (unsigned int i = 0; i < face_dofs.size(); ++i)
                if (fe.face_system_to_component_index(i, f).first < dim)
                  massless.push_back(face_dofs[i]);
            }
    std::sort(massless.begin(), massless.end());
    massless.erase(std::unique(massless.begin(), massless.end()),
                   massless.end());

    // The owned u DoFs with mass that no boundary condition prescribes (u
    // is block 0: its global and block indices agree).
    const auto &handler = discretisation.dof_handler;
    IndexSet    displacements(handler.n_dofs());
    displacements.add_range(0, discretisation.owned_partitioning[0].size());
    measured = discretisation.locally_owned_dofs & displacements;
    IndexSet without_mass(handler.n_dofs());
    without_mass.add_indices(massless.begin(), massless.end());
    measured.subtract_set(without_mass);
    for (const BoundaryCondition &bc : boundary_conditions)
      if (bc.has_dirichlet())
        measured.subtract_set(DoFTools::extract_boundary_dofs(
          handler, bc.dirichlet_mask(), {bc.boundary_id}));
  }



  void
  TimeIntegrator::start()
  {
    std::map<types::material_id, std::unique_ptr<FunctionParser<dim>>> initial;
    for (const BodyParameters &b : bodies)
      {
        auto f = std::make_unique<FunctionParser<dim>>(dim);
        f->initialize(coordinate_variables(), b.initial_velocity, {});
        initial.emplace(b.material_id, std::move(f));
      }
    velocity              = 0.;
    const IndexSet &owned = discretisation.locally_owned_dofs;
    std::vector<types::global_dof_index> indices;
    for (const auto &cell : discretisation.dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        const FunctionParser<dim> &v  = *initial.at(cell->material_id());
        const FiniteElement<dim>  &fe = cell->get_fe();
        indices.resize(fe.n_dofs_per_cell());
        cell->get_dof_indices(indices);
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const unsigned int c = fe.system_to_component_index(i).first;
            if (c >= dim || !owned.is_element(indices[i]))
              continue;
            const auto       base = fe.system_to_base_index(i);
            const Point<dim> X =
              discretisation.mapping[0].transform_unit_to_real_cell(
                cell,
                fe.base_element(base.first.first)
                  .unit_support_point(base.second));
            velocity(indices[i]) = v.value(X, c);
          }
      }
    velocity.compress(VectorOperation::insert);
    discretisation.hanging_node_constraints.distribute(velocity);
    acceleration          = 0.;
    inertial_acceleration = 0.;
  }



  const InertiaTerms &
  TimeIntegrator::initial_terms()
  {
    velocity_ghosted  = velocity;
    mean_acceleration = 0.;
    reset_terms();
    terms.velocity          = &velocity_ghosted;
    terms.mean_acceleration = &mean_acceleration;
    return terms;
  }



  const InertiaTerms &
  TimeIntegrator::step_terms(const BlockVector &u_n, const double dt)
  {
    // a_m = c (u - u*) with c = (1 - a_B)/(beta dt^2) and
    // u* = u_n + dt v_n + dt^2 ((1/2 - beta) - a_B beta/(1 - a_B)) a_n.
    // (u_n may hold ghost entries: star is an owned copy.)
    BlockVector star(discretisation.owned_partitioning,
                     discretisation.dof_handler.get_communicator());
    star = u_n;
    star.block(Block::displacement)
      .add(dt,
           velocity.block(Block::displacement),
           dt * dt * ((0.5 - beta) - alpha_b * beta / (1. - alpha_b)),
           acceleration.block(Block::displacement));
    for (unsigned int b = 0; b < Block::n_blocks; ++b)
      if (b != Block::displacement)
        star.block(b) = 0.;
    target = star;
    reset_terms();
    terms.mass_factor = (1. - alpha_b) / (beta * dt * dt);
    terms.target      = &target;
    return terms;
  }



  const InertiaTerms &
  TimeIntegrator::commit_terms(const BlockVector &u,
                               const BlockVector &u_n,
                               const double       dt)
  {
    const unsigned int d = Block::displacement;
    // a_n+1 = (u - u_n - dt v_n - dt^2 (1/2 - beta) a_n)/(beta dt^2).
    new_acceleration = 0.;
    auto &a          = new_acceleration.block(d);
    a                = u.block(d);
    a -= u_n.block(d);
    a.add(-dt,
          velocity.block(d),
          -dt * dt * (0.5 - beta),
          acceleration.block(d));
    a *= 1. / (beta * dt * dt);
    new_velocity = velocity;
    new_velocity.block(d).add(dt * (1. - gamma),
                              acceleration.block(d),
                              dt * gamma,
                              a);
    new_inertial_acceleration = 0.;
    new_inertial_acceleration.block(d).add(1. - alpha_b,
                                           a,
                                           alpha_b,
                                           acceleration.block(d));
    BlockVector mean = new_inertial_acceleration;
    mean += inertial_acceleration;
    mean *= 0.5;
    mean_acceleration       = mean;
    velocity_ghosted        = new_velocity;
    terms.velocity          = &velocity_ghosted;
    terms.mean_acceleration = &mean_acceleration;
    return terms;
  }



  double
  TimeIntegrator::local_error(const BlockVector &u,
                              const BlockVector &u_n,
                              const double       dt) const
  {
    // a_n+1 - a_n = (u - u_n - dt v_n - dt^2 a_n/2)/(beta dt^2), so
    // e = (beta - 1/6)/beta (u - u_n - dt v_n - dt^2 a_n/2).
    const unsigned int d        = Block::displacement;
    const auto        &v        = velocity.block(d);
    const auto        &a        = acceleration.block(d);
    const double       factor   = (beta - 1. / 6.) / beta;
    double             local[2] = {0., 0.};
    for (const auto i : measured)
      {
        const double step = u.block(d)(i) - u_n.block(d)(i);
        const double e    = factor * (step - dt * v(i) - 0.5 * dt * dt * a(i));
        local[0]          = std::max(local[0], std::abs(e));
        local[1]          = std::max(local[1], std::abs(step));
      }
    double global[2];
    Utilities::MPI::max(ArrayView<const double>(local, 2),
                        discretisation.dof_handler.get_communicator(),
                        ArrayView<double>(global, 2));
    return global[1] > 0. ? global[0] / global[1] : 0.;
  }



  void
  TimeIntegrator::accept()
  {
    velocity              = new_velocity;
    acceleration          = new_acceleration;
    inertial_acceleration = new_inertial_acceleration;
  }



  const InertiaTerms &
  TimeIntegrator::accepted_terms(const BlockVector &u_n)
  {
    BlockVector star(discretisation.owned_partitioning,
                     discretisation.dof_handler.get_communicator());
    star = u_n;
    star -= inertial_acceleration;
    for (unsigned int b = 0; b < Block::n_blocks; ++b)
      if (b != Block::displacement)
        star.block(b) = 0.;
    target = star;
    reset_terms();
    terms.mass_factor = 1.;
    terms.target      = &target;
    return terms;
  }



  std::vector<BlockVector>
  TimeIntegrator::ghosted_vectors() const
  {
    std::vector<BlockVector> copies;
    for (const BlockVector *v :
         {&velocity, &acceleration, &inertial_acceleration})
      {
        copies.emplace_back(discretisation.owned_partitioning,
                            discretisation.relevant_partitioning,
                            discretisation.dof_handler.get_communicator());
        copies.back() = *v;
      }
    return copies;
  }
} // namespace DuctileContact
