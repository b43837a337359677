// ContactProblem: the search for close face pairs (bounding boxes of the
// slave faces enlarged by the search radius against an R-tree of the master
// faces) and the check that no pair was missed.
#include <deal.II/base/bounding_box.h>
#include <deal.II/numerics/rtree.h>

#include <ductile_contact/contact/contact_problem.h>
#include <ductile_contact/contact/mortar_segments.h>
#include <ductile_contact/core/input_error.h>

#include <algorithm>
#include <iterator>
#include <set>
#include <sstream>

namespace DuctileContact
{
  using namespace dealii;



  namespace
  {
    BoundingBox<dim>
    face_box(const ContactSurface &surface, const unsigned int f, double r)
    {
      std::vector<Point<dim>> points;
      for (const unsigned int n : surface.faces[f].nodes)
        points.push_back(surface.nodes[n].current);
      BoundingBox<dim> box(points);
      box.extend(r);
      return box;
    }
  } // namespace



  std::vector<std::vector<unsigned int>>
  ContactProblem::search(const Pair &pair, const double radius)
  {
    std::vector<std::pair<BoundingBox<dim>, unsigned int>> boxes;
    for (unsigned int m = 0; m < pair.master.faces.size(); ++m)
      boxes.emplace_back(face_box(pair.master, m, 0.), m);
    const auto tree = pack_rtree(boxes);

    std::vector<std::vector<unsigned int>> candidates(pair.slave.faces.size());
    for (unsigned int s = 0; s < pair.slave.faces.size(); ++s)
      {
        std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
        tree.query(boost::geometry::index::intersects(
                     face_box(pair.slave, s, radius)),
                   std::back_inserter(hits));
        for (const auto &hit : hits)
          candidates[s].push_back(hit.second);
        std::sort(candidates[s].begin(), candidates[s].end());
      }
    return candidates;
  }



  double
  ContactProblem::search_radius(const Pair &pair)
  {
    if (pair.given_radius > 0.)
      return pair.widen * pair.given_radius;
    const auto largest_motion = [](const ContactSurface          &surface,
                                   const std::vector<Point<dim>> &committed) {
      double motion = 0.;
      for (unsigned int n = 0; n < surface.nodes.size(); ++n)
        motion =
          std::max(motion, surface.nodes[n].current.distance(committed[n]));
      return motion;
    };
    const double motion = largest_motion(pair.slave, pair.slave_committed) +
                          largest_motion(pair.master, pair.master_committed);
    return pair.widen *
           (reach(pair) + std::max(0.25 * pair.face_size, 2. * motion));
  }



  std::string
  ContactProblem::missed_pair(
    const Pair                                   &pair,
    const std::vector<std::vector<unsigned int>> &near)
  {
    for (unsigned int f = 0; f < pair.slave.faces.size(); ++f)
      {
        const auto &candidates = pair.candidates[f];
        for (const unsigned int c : near[f])
          if (!std::binary_search(candidates.begin(), candidates.end(), c) &&
              faces_may_overlap(pair.slave_faces[f],
                                pair.master.current_face(c)))
            {
              std::ostringstream s;
              s << "contact pair " << pair.index + 1 << ": the master face at ("
                << pair.master.current_face(c).position(ContactFace::centre())
                << ") m came within reach of the slave face at ("
                << pair.slave_faces[f].position(ContactFace::centre())
                << ") m but is not among the candidates of the step "
                   "(search radius "
                << pair.search_radius
                << " m); the step is redone with the radius doubled";
              return s.str();
            }
      }
    return "";
  }



  std::vector<std::pair<unsigned int, unsigned int>>
  ContactProblem::close_face_pairs(
    const Pair                                   &pair,
    const std::vector<std::vector<unsigned int>> &near)
  {
    // A slave face is integrated whole or not at all: once one of its
    // candidates is within reach, against every candidate. Integrated
    // against the near ones only, the reach would cut the face where it is
    // about reach() from the master, and a node left with a sliver of its
    // support gets a weighted gap of either sign (the dual basis functions
    // change sign on a face): a node millimetres from the master could
    // turn active in one iterate and inactive in the next as the cut moved
    // (semi-smooth Newton then cycled between the two states).
    std::vector<std::pair<unsigned int, unsigned int>> close;
    for (unsigned int f = 0; f < pair.slave.faces.size(); ++f)
      {
        const auto &candidates = pair.candidates[f];
        if (std::find_first_of(near[f].begin(),
                               near[f].end(),
                               candidates.begin(),
                               candidates.end()) == near[f].end())
          continue;
        for (const unsigned int c : candidates)
          close.emplace_back(f, c);
      }
    return close;
  }

} // namespace DuctileContact
