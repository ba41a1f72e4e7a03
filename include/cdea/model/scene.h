#pragma once
// The physical scene in SI units, independent of any discretization: what the
// FE model and the shooting model both solve.
//
// Radii a (disk) and b (frame) and the ring edges r_v are measured on the
// pre-stretched flat film. The membrane occupies A = a/lam_pre <= R <= B = b/lam_pre
// in the undeformed film, and ring edge r_v sits at R_v = r_v/lam_pre.

#include <cdea/material/gent_dielectric.h>
#include <cdea/material/law_factory.h>
#include <cdea/model/voltage_path.h>

#include <map>
#include <string>
#include <vector>

namespace cdea
{
  struct Scene
  {
    double            disk_radius  = 14e-3; ///< a (m)
    double            frame_radius = 42e-3; ///< b (m)
    double            prestretch   = 2.5;   ///< lam_pre (-)
    MaterialConstants material{25.1e3, 270., 3.98e-11, 1e-3};
    /// The law of Material/Model (law_factory.h): its registered name and
    /// the entries the laws declare in subsection Material, in the parameter
    /// file's units (the one exception to SI here); `material` holds the
    /// film's constants. Every model of the scene (FE, shooting, the
    /// studies' models) builds this law.
    std::string                   material_model = LawSettings().model;
    std::map<std::string, double> law_constants;
    std::map<std::string, std::string> law_texts; ///< the laws' text entries (lists, names)
    double            mass    = 0.28; ///< kg
    double            gravity = 9.81; ///< m/s^2
    /// n+1 increasing ring edges r/a for n rings; first 1, last b/a.
    std::vector<double> ring_edges_over_a{1., 3.};
    VoltagePath         path;

    double       dead_load() const { return mass * gravity; } ///< F (N)
    unsigned int n_rings() const { return ring_edges_over_a.size() - 1; }
    double       inner_reference_radius() const { return disk_radius / prestretch; }
    double       outer_reference_radius() const { return frame_radius / prestretch; }
    /// Ring edges R_v in the undeformed film (m), n+1 values from A to B.
    std::vector<double> reference_ring_edges() const;
    /// Index of the ring that holds reference radius R (edges belong to the
    /// ring outside them, the last edge to the last ring).
    unsigned int ring_of(double R) const;
    /// The settings of the scene's law (material_model, material, law_constants,
    /// law_texts).
    LawSettings law_settings() const;
    /// The scene's law, built from law_settings() (InputError if a constant
    /// is outside the law's range).
    std::shared_ptr<const MembraneLaw> law() const;
  };

  /// The paper's actuator (the defaults above) with the given ring edges
  /// (r/a) and voltage-path waypoints in kV: for tests, benchmarks and studies.
  Scene paper_scene(const std::vector<double>              &ring_edges_over_a,
                    const std::vector<std::vector<double>> &waypoints_kV);

  /// @p base with the viscoelastic film (Material/Model = viscoelastic):
  /// network A its film, a relaxation spectrum of Gent branches with the
  /// moduli @p moduli_kPa (kPa), relaxation times @p times_s (s) and Jlim
  /// @p branch_jlim: for tests, benchmarks and studies.
  Scene spectrum_scene(Scene base, const std::vector<double> &moduli_kPa,
                       const std::vector<double> &times_s, double branch_jlim);
} // namespace cdea
