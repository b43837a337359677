#include <deal.II/lac/trilinos_block_sparse_matrix.h>

#include <ductile_contact/assembly/scatter.h>
#include <ductile_contact/contact/contact_problem.h>
#include <ductile_contact/contact/contact_writer.h>
#include <ductile_contact/contact/mortar_operators.h>
#include <ductile_contact/core/input_error.h>

#include <algorithm>
#include <set>
#include <sstream>
#include <unordered_set>

namespace DuctileContact
{
  using namespace dealii;



  ContactProblem::ContactProblem(
    const std::deque<ContactPairParameters>                    &pairs,
    const Discretisation                                       &discretisation,
    const std::map<types::material_id, const BodyParameters *> &bodies)
      : pairs(pairs)
      , discretisation(discretisation)
      , bodies(bodies)
  {
  }



  const Enforcement *
  ContactProblem::enforcement_of(const ContactEnforcement kind)
  {
    std::unique_ptr<Enforcement> &e = enforcements[kind];
    if (!e)
      e = make_enforcement(kind, *this);
    return e.get();
  }



  void
  ContactProblem::setup()
  {
    data.assign(pairs.size(), Pair());
    surface = IndexSet(discretisation.dof_handler.n_dofs());
    summaries.assign(pairs.size(), ContactPairSummary());
    if (output_records.size() != pairs.size()) // kept over mesh changes
      output_records.assign(pairs.size(), {});
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        const ContactPairParameters &prm  = pairs[p];
        Pair                        &pair = data[p];
        pair.slave.gather(discretisation, prm.slave_boundary_id);
        pair.master.gather(discretisation, prm.master_boundary_id);
        const std::string s = prm.subsection() + "/";
        check_input(!pair.slave.faces.empty(),
                    s + "Slave boundary id",
                    std::to_string(prm.slave_boundary_id),
                    "the id of a boundary of the mesh (no face has it)");
        check_input(!pair.master.faces.empty(),
                    s + "Master boundary id",
                    std::to_string(prm.master_boundary_id),
                    "the id of a boundary of the mesh (no face has it)");

        // eps_N = factor E / h, E the smaller Young's modulus of the two
        // bodies (the interface is as stiff as the softer one).
        const auto youngs_modulus = [&](const ContactSurface &side) {
          const auto body = bodies.find(side.faces[0].material_id);
          Assert(body != bodies.end(), ExcInternalError());
          const double mu    = body->second->shear_modulus;
          const double kappa = body->second->bulk_modulus;
          return 9. * kappa * mu / (3. * kappa + mu);
        };
        const double E =
          std::min(youngs_modulus(pair.slave), youngs_modulus(pair.master));
        const double h    = pair.slave.smallest_face_size();
        pair.index        = p;
        pair.dual         = prm.multiplier_basis == MultiplierBasis::dual;
        pair.enforcement  = enforcement_of(prm.enforcement);
        pair.law.penalty  = prm.penalty_factor * E / h;
        pair.law.friction = prm.friction_coefficient;
        pair.law.tangential_penalty = prm.tangential_penalty_factor * E / h;
        // Active also when just touching (a gap at round-off level): then
        // the tangent holds the contact stiffness of a closed interface, so
        // that bodies which only touch at the start are not free.
        pair.law.activation_threshold = 1e-12 * pair.law.penalty * h;
        pair.face_size                = h;
        pair.tolerance                = prm.penetration_tolerance * h;
        pair.given_radius             = prm.search_radius;
        pair.candidates.assign(pair.slave.faces.size(), {});
        for (const ContactSurface *side : {&pair.slave, &pair.master})
          for (const auto &node : side->nodes)
            for (const auto d : node.dofs)
              surface.add_index(d);
        pair.multiplier.assign(pair.slave.nodes.size(), 0.);
        for (const auto &node : pair.slave.nodes)
          pair.slave_committed.push_back(node.reference);
        for (const auto &node : pair.master.nodes)
          pair.master_committed.push_back(node.reference);
        pair.committed_traction.assign(pair.slave.nodes.size(),
                                       Tensor<1, dim>());
        pair.committed_multiplier = pair.multiplier;
      }
    surface.compress();
    for (const Pair &pair : data)
      pair.enforcement->check(pair);
    bulk_rows_here = slave_rows_complete_here();
  }



  bool
  ContactProblem::slave_rows_complete_here() const
  {
    // The DoFs of the slave nodes this rank condenses.
    std::unordered_set<types::global_dof_index> rows;
    for (const Pair &pair : data)
      if (pair.condenses())
        for (const auto &node : pair.slave.nodes)
          if (discretisation.locally_owned_dofs.is_element(node.dofs[0]))
            rows.insert(node.dofs.begin(), node.dofs.end());
    bool here = true;
    for_each_cell_row([](const auto &cell) { return cell->is_ghost(); },
                      [&](const types::global_dof_index row, const auto &) {
                        here = here && rows.count(row) == 0;
                      });
    return Utilities::MPI::min(here ? 1 : 0,
                               discretisation.dof_handler.get_communicator()) ==
           1;
  }



  bool
  ContactProblem::begin_step(const TrilinosWrappers::MPI::BlockVector &u)
  {
    outer_updates = 0;
    bool changed  = false;
    for (Pair &pair : data)
      {
        pair.slave.update(u, discretisation);
        pair.master.update(u, discretisation);
        pair.multiplier = pair.committed_multiplier;
        if (!pair.missed.empty())
          pair.widen *= 2.;
        pair.missed.clear();
        pair.search_radius = search_radius(pair);

        std::vector<std::vector<unsigned int>> candidates =
          search(pair, pair.search_radius);
        if (candidates != pair.candidates)
          {
            changed         = true;
            pair.candidates = std::move(candidates);
          }
      }
    return changed;
  }



  std::string
  ContactProblem::fault() const
  {
    for (const Pair &pair : data)
      if (!pair.missed.empty())
        return pair.missed;
    return "";
  }



  void
  ContactProblem::add_constrained_rows(ConstrainedNodes &nodes) const
  {
    for (const Pair &pair : data)
      nodes.insert(nodes.end(),
                   pair.constrained_rows.begin(),
                   pair.constrained_rows.end());
  }



  void
  ContactProblem::assemble(const TrilinosWrappers::MPI::BlockVector &u,
                           const AffineConstraints<double> &constraints,
                           const AssemblyTargets           &targets)
  {
    AffineConstraints<double> all_constraints;
    extend_constraints(constraints, all_constraints);
    bool condensing = false, other = false;
    for (Pair &pair : data)
      {
        pair.slave.update(u, discretisation);
        pair.master.update(u, discretisation);
        integrate(pair,
                  targets.tangent != nullptr &&
                    pair.enforcement->linearises_in_integration());
        condensing = condensing || pair.condenses();
        if (!pair.condenses())
          {
            other = true;
            pair.enforcement->assemble(pair, all_constraints, targets);
          }
      }
    // Without a condensing pair the one compress of the assembly (the bulk
    // assembly leaves its terms to it: needs_compressed_bulk()). Each
    // compress costs ~8 ms per tangent on prm/two_bodies.prm, with or
    // without new entries.
    if (!condensing)
      {
        compress(targets);
        return;
      }
    if (other)
      compress(targets);
    // The condensation reads the complete bulk rows of the slave nodes:
    // compressed, or complete where they are (slave_rows_complete_here()).
    for (Pair &pair : data)
      if (pair.condenses())
        pair.enforcement->assemble(pair, all_constraints, targets);
    compress(targets);
  }



  bool
  ContactProblem::augment()
  {
    bool done = true;
    for (unsigned int p = 0; p < data.size(); ++p)
      done = data[p].enforcement->outer_update(data[p], summaries[p]) && done;
    return done;
  }



  unsigned int
  ContactProblem::max_outer_updates() const
  {
    unsigned int n = 0;
    for (const ContactPairParameters &p : pairs)
      n = std::max(n, p.max_augmentations);
    return n;
  }



  bool
  ContactProblem::outer_update(std::string &report)
  {
    // The summaries are those of the last assembly, before the update.
    std::ostringstream text;
    text << "multipliers updated; largest penetration before the update:";
    for (const ContactPairSummary &summary : summaries)
      text << " " << summary.max_penetration << " m";
    const bool done = augment();
    if (!done)
      {
        ++outer_updates;
        report = text.str();
      }
    return done;
  }



  double
  ContactProblem::dissipation() const
  {
    double d = 0.;
    for (const ContactPairSummary &summary : summaries)
      d += summary.dissipation;
    return d;
  }



  void
  ContactProblem::commit()
  {
    for (Pair &pair : data)
      {
        for (unsigned int j = 0; j < pair.nodal.size(); ++j)
          {
            pair.committed_multiplier[j] = pair.nodal[j].pressure;
            pair.committed_traction[j]   = pair.nodal[j].traction;
          }
        pair.dissipation += pair.step_dissipation;
        pair.step_dissipation = 0.;
        for (unsigned int j = 0; j < pair.slave.nodes.size(); ++j)
          pair.slave_committed[j] = pair.slave.nodes[j].current;
        for (unsigned int l = 0; l < pair.master.nodes.size(); ++l)
          pair.master_committed[l] = pair.master.nodes[l].current;
      }
  }



  void
  ContactProblem::write_output(const std::string &directory,
                               const OutputFormat format,
                               const unsigned int step,
                               const double       time)
  {
    for (unsigned int p = 0; p < data.size(); ++p)
      {
        const Pair      &pair = data[p];
        ContactNodalData nodal;
        nodal.surface = &pair.slave;
        for (unsigned int j = 0; j < pair.nodal.size(); ++j)
          {
            const NodalAggregates &a = pair.aggregates[j];
            nodal.pressure.push_back(pair.nodal[j].pressure);
            nodal.normal.push_back(a.normal);
            nodal.active.push_back(pair.nodal[j].active);
            nodal.slip.push_back(pair.nodal[j].slip);
            nodal.traction.push_back(pair.nodal[j].traction);
            nodal.friction_state.push_back(pair.nodal[j].friction_state);
            nodal.gap.push_back(a.area > 0. ? pair.nodal[j].gap / a.area : 0.);
          }
        // Before the first assembly (step 0) nothing is computed yet.
        const std::size_t n = pair.slave.nodes.size();
        nodal.pressure.resize(n, 0.);
        nodal.normal.resize(n);
        nodal.slip.resize(n);
        nodal.traction.resize(n);
        nodal.active.resize(n, false);
        nodal.friction_state.resize(n, 0);
        nodal.gap.resize(n, 0.);
        write_contact_surface(nodal,
                              directory,
                              "contact" + std::to_string(pairs[p].number),
                              step,
                              time,
                              format,
                              discretisation.dof_handler.get_communicator(),
                              output_records[p]);
      }
  }


  void
  ContactProblem::add_columns(Statistics &statistics) const
  {
    const char *xyz[] = {"x", "y", "z"};
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        const ContactPairSummary &c = summaries[p];
        const std::string name = "contact" + std::to_string(pairs[p].number);
        for (unsigned int d = 0; d < dim; ++d)
          statistics.add(name + "_force_" + xyz[d], c.force[d]);
        statistics.add(name + "_area", c.area);
        statistics.add(name + "_active_nodes", c.active_nodes);
        statistics.add(name + "_max_penetration", c.max_penetration);
        statistics.add(name + "_max_pressure", c.max_pressure);
        statistics.add(name + "_min_pressure", c.min_pressure);
        for (unsigned int d = 0; d < dim; ++d)
          statistics.add(name + "_friction_" + xyz[d], c.friction_force[d]);
        statistics.add(name + "_sticking_nodes", c.sticking_nodes);
        statistics.add(name + "_slipping_nodes", c.slipping_nodes);
        statistics.add(name + "_max_slip", c.max_slip);
        statistics.add(name + "_dissipation", c.dissipation);
      }
    statistics.add("contact_augmentations", outer_updates);
  }
} // namespace DuctileContact
