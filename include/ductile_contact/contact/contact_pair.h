#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <ductile_contact/contact/contact_face.h>
#include <ductile_contact/contact/contact_surface.h>
#include <ductile_contact/contact/mortar_operators.h>
#include <ductile_contact/contact/nodal_contact.h>
#include <ductile_contact/solver/constrained_rows.h>

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace DuctileContact
{
  class Enforcement;

  /// State of one contact pair after an assembly (same on every rank).
  struct ContactPairSummary
  {
    /// Force the slave body exerts on the master, sum of lambda_j A_j n_j
    /// with n_j the slave's outward normal [N] (its negative acts on the
    /// slave).
    dealii::Tensor<1, dim> force;
    /// Sum of A_j over the active slave nodes [m^2].
    double       area         = 0.;
    unsigned int active_nodes = 0;
    /// Largest nodal penetration max(0, -g_j / A_j) over the slave nodes
    /// [m].
    double max_penetration = 0.;
    /// Largest and smallest nodal pressure lambda_j over the active nodes
    /// [Pa].
    double max_pressure = 0., min_pressure = 0.;
    /// Friction force the slave exerts on the master, sum of A_j t_T,j [N].
    dealii::Tensor<1, dim> friction_force;
    unsigned int           sticking_nodes = 0, slipping_nodes = 0;
    /// Largest slip |s_j| of a node in contact in this step [m].
    double max_slip = 0.;
    /// Frictional dissipation (47) up to this state [J].
    double dissipation = 0.;
  };



  /**
   * One contact pair: its surfaces, the candidates of the step, the mortar
   * operators D and M and the nodal aggregates of the last assembly, the
   * nodal states and multipliers, and the committed state of the last
   * accepted step. ContactProblem computes the geometry and the operators;
   * the pair's Enforcement turns them into tractions.
   */
  struct ContactPair
  {
    unsigned int   index = 0; ///< position in pairs and summaries
    ContactSurface slave, master;
    bool           dual = true; ///< dual or standard multiplier basis
    /// How the pair enforces contact (owned by its ContactProblem).
    const Enforcement     *enforcement = nullptr;
    NodalContactParameters law;
    double                 search_radius = 0., tolerance = 0.; ///< [m]
    double                 face_size = 0.; ///< smallest slave face size [m]
    /// Contact pair/Search radius (0: from the step's motion, see
    /// search_radius()) [m].
    double given_radius = 0.;
    /// Doubles in every step in which a face pair came within reach
    /// outside the candidates.
    double widen = 1.;
    /// Of the last assembly: a face pair within reach that is no
    /// candidate ("" when there is none).
    std::string missed;
    /// Node positions of the last accepted step (slip increments).
    std::vector<dealii::Point<dim>> slave_committed, master_committed;
    /// Tangential traction per slave node of the last accepted step [Pa].
    std::vector<dealii::Tensor<1, dim>> committed_traction;
    double step_dissipation = 0., dissipation = 0.; ///< [J]
    /// Candidate master faces of each slave face.
    std::vector<std::vector<unsigned int>> candidates;
    /// Multipliers lambdahat per slave node: iterate and committed [Pa].
    std::vector<double> multiplier, committed_multiplier;
    // Of the last assembly:
    /// Current slave faces.
    std::vector<ContactFace> slave_faces;
    /// (slave face, master face) pairs that overlap.
    std::vector<std::pair<unsigned int, unsigned int>> overlaps;
    /// Whether integrate() kept derivatives: then this rank's share of
    /// the face pairs, overlaps[linearised_pairs[k]], has its dD and dM
    /// in linearised_operators[k] (the vector only grows, and is reused).
    bool                           linearised_here = false;
    std::vector<std::size_t>       linearised_pairs;
    std::vector<FacePairOperators> linearised_operators;
    /// Per slave node: D_jk, M_jl, the aggregates (nodal_contact.h), the
    /// length of the summed face normals n_j is made from, the state.
    std::vector<std::map<unsigned int, double>> D, M;
    /// Semi-smooth Newton with hanging slave nodes: M with the row of
    /// each hanging node added, times its weight, to its parents' rows
    /// (fold_hanging_nodes()); empty otherwise.
    std::vector<std::map<unsigned int, double>> folded_M;
    /// Of the last tangent assembly: the slave nodes whose rows hold
    /// constraints (semi-smooth Newton's active nodes), in their frames.
    ConstrainedNodes               constrained_rows;
    std::vector<NodalAggregates>   aggregates;
    std::vector<double>            normal_length;
    std::vector<NodalContactState> nodal;

    /// Whether slave node @p j has a share of the overlap (only those
    /// carry contact).
    bool
    carries_contact(const unsigned int j) const;

    /// The slave weights D needs: a condensing enforcement lumps D to its
    /// row's node (D[j] then holds only D_jj, the row sum).
    SlaveWeights
    slave_weights() const;

    /// Whether the pair's enforcement condenses the tractions from the bulk
    /// rows of the slave nodes (Enforcement::condenses()).
    bool
    condenses() const;

    /// The master weights of node @p j's traction: folded_M[j] if
    /// there is one, else M[j].
    const std::map<unsigned int, double> &
    master_row(const unsigned int j) const
    {
      return folded_M.empty() ? M[j] : folded_M[j];
    }
  };
} // namespace DuctileContact
