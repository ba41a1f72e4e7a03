// The one FE translation unit that includes deal.II: mesh, FE space, dof
// numbering and quadrature, turned into the plain arrays of Discretization.

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_renumbering.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>

#include <deal.II/hp/fe_collection.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <cdea/fe/discretization.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <numeric>

namespace cdea
{
  using namespace dealii;

  namespace
  {
    /// Element lengths of one ring: geometric, smallest at the ring's inner
    /// edge, the last @p grading times the first.
    std::vector<double> graded_steps(const double length, const unsigned int n,
                                     const double grading)
    {
      std::vector<double> steps(n, length / n);
      if (n > 1 && grading > 1.)
        {
          const double q  = std::pow(grading, 1. / (n - 1));
          const double h0 = length * (q - 1.) / (std::pow(q, n) - 1.);
          for (unsigned int k = 0; k < n; ++k)
            steps[k] = h0 * std::pow(q, k);
        }
      return steps;
    }
  } // namespace

  namespace
  {
    /// The shape functions of @p fe at @p points (weights kept with them).
    ShapeTable tabulate(const FESystem<1> &fe, const std::vector<double> &points,
                        const std::vector<double> &weights)
    {
      const unsigned int n = fe.n_dofs_per_cell();
      ShapeTable         t;
      t.points  = points;
      t.weights = weights;
      t.value.resize(points.size() * n);
      t.derivative.resize(points.size() * n);
      for (unsigned int q = 0; q < points.size(); ++q)
        for (unsigned int i = 0; i < n; ++i)
          {
            t.value[q * n + i]      = fe.shape_value(i, Point<1>(points[q]));
            t.derivative[q * n + i] = fe.shape_grad(i, Point<1>(points[q]))[0];
          }
      return t;
    }

    ShapeTable tabulate(const FESystem<1> &fe, const Quadrature<1> &rule)
    {
      std::vector<double> points, weights;
      for (unsigned int q = 0; q < rule.size(); ++q)
        {
          points.push_back(rule.point(q)[0]);
          weights.push_back(rule.weight(q));
        }
      return tabulate(fe, points, weights);
    }

    /// The FE space of degree p and its shape tables, built once per degree
    /// (and number of samples) and process, read-only once built: deal.II's
    /// FE_Q and FESystem constructors, its Gauss rules and shape function
    /// evaluations cost more than the rest of a small model. The DoFHandler
    /// gets the space as a collection, which it copies by reference; given
    /// the element itself, it would build a copy for every model.
    struct FeSpace
    {
      explicit FeSpace(const unsigned int degree)
        : collection(FESystem<1>(FE_Q<1>(degree), 2))
        , fe(dynamic_cast<const FESystem<1> &>(collection[0]))
        , energy_rule(tabulate(fe, QGauss<1>(degree + 1)))
        , volume_rule(tabulate(fe, QGauss<1>(2 * degree)))
        , left_end(tabulate(fe, {0.}, {}))
      {}
      const hp::FECollection<1> collection;
      const FESystem<1>        &fe;
      const ShapeTable          energy_rule, volume_rule, left_end;
      /// samples_per_element + 1 equidistant points, by samples_per_element
      /// (filled under the lock of shared_space()).
      std::map<unsigned int, ShapeTable> samples;
    };

    std::mutex &space_lock()
    {
      static std::mutex lock;
      return lock;
    }

    std::shared_ptr<FeSpace> shared_space(const unsigned int degree)
    {
      static std::map<unsigned int, std::shared_ptr<FeSpace>> built;
      const std::lock_guard<std::mutex>                       guard(space_lock());
      auto                                                   &space = built[degree];
      if (!space)
        space = std::make_shared<FeSpace>(degree);
      return space;
    }

    ShapeTable equidistant_samples(FeSpace &space, const unsigned int samples_per_element)
    {
      const std::lock_guard<std::mutex> guard(space_lock());
      auto [table, inserted] = space.samples.try_emplace(samples_per_element);
      if (inserted)
        {
          std::vector<double> points;
          for (unsigned int k = 0; k <= samples_per_element; ++k)
            points.push_back(double(k) / samples_per_element);
          table->second = tabulate(space.fe, points, {});
        }
      return table->second;
    }
  } // namespace

  struct Discretization::Impl
  {
    explicit Impl(const unsigned int degree)
      : space(shared_space(degree))
    {}
    std::shared_ptr<FeSpace> space;
  };

  Discretization::Discretization(const Scene &scene, const FeDiscretization &settings_in)
    : settings(settings_in)
    , impl(std::make_unique<Impl>(settings_in.degree))
  {
    const auto          edges = scene.reference_ring_edges();
    std::vector<double> steps;
    for (unsigned int ring = 0; ring < scene.n_rings(); ++ring)
      {
        const auto s =
          graded_steps(edges[ring + 1] - edges[ring], settings.elements_per_ring, settings.grading);
        steps.insert(steps.end(), s.begin(), s.end());
      }
    Triangulation<1> triangulation;
    GridGenerator::subdivided_hyper_rectangle(triangulation, {steps}, Point<1>(edges.front()),
                                              Point<1>(edges.back()));
    for (auto &cell : triangulation.active_cell_iterators())
      cell->set_material_id(scene.ring_of(cell->center()[0]));
    triangulation.refine_global(settings.refinements);

    DoFHandler<1> dof_handler(triangulation);
    dof_handler.distribute_dofs(impl->space->collection);
    DoFRenumbering::Cuthill_McKee(dof_handler);
    n_dofs_        = dof_handler.n_dofs();
    dofs_per_cell_ = impl->space->fe.n_dofs_per_cell();
    for (unsigned int i = 0; i < dofs_per_cell_; ++i)
      component.push_back(impl->space->fe.system_to_component_index(i).first);

    // Cells sorted by radius.
    std::vector<DoFHandler<1>::active_cell_iterator> sorted;
    for (const auto &cell : dof_handler.active_cell_iterators())
      sorted.push_back(cell);
    std::sort(sorted.begin(), sorted.end(), [](const auto &a, const auto &b) {
      return a->vertex(0)[0] < b->vertex(0)[0];
    });
    std::vector<types::global_dof_index> dofs(dofs_per_cell_);
    const auto &unit_points = impl->space->fe.get_unit_support_points();
    support_radius.assign(n_dofs_, 0.);
    support_component.assign(n_dofs_, 0);
    for (const auto &cell : sorted)
      {
        const double x0 = cell->vertex(0)[0], h = cell->vertex(1)[0] - x0;
        cells.push_back({x0, h, static_cast<unsigned int>(cell->material_id())});
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs_per_cell_; ++i)
          {
            cell_dofs.push_back(dofs[i]);
            support_radius[dofs[i]]    = x0 + h * unit_points[i][0];
            support_component[dofs[i]] = component[i];
          }
        for (const auto a : dofs)
          for (const auto b : dofs)
            bandwidth_ = std::max<unsigned int>(bandwidth_, a > b ? a - b : b - a);
      }
    r_inner = sorted.front()->vertex_dof_index(0, 0);
    z_inner = sorted.front()->vertex_dof_index(0, 1);
    r_outer = sorted.back()->vertex_dof_index(1, 0);
    z_outer = sorted.back()->vertex_dof_index(1, 1);
    constrained = {r_inner, r_outer, z_outer};

    energy_rule = impl->space->energy_rule;
    volume_rule = impl->space->volume_rule;
    left_end    = impl->space->left_end;
    samples     = equidistant_samples(*impl->space, settings.samples_per_element);
  }

  Discretization::~Discretization() = default;

  void Discretization::shape_at(const double xi, std::vector<double> &value,
                                std::vector<double> &derivative) const
  {
    value.resize(dofs_per_cell_);
    derivative.resize(dofs_per_cell_);
    for (unsigned int i = 0; i < dofs_per_cell_; ++i)
      {
        value[i]      = impl->space->fe.shape_value(i, Point<1>(xi));
        derivative[i] = impl->space->fe.shape_grad(i, Point<1>(xi))[0];
      }
  }
} // namespace cdea
