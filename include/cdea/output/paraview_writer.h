#pragma once
// ParaView output of a run: a PVD collection with one VTK XML unstructured-grid
// file (VTU) per converged step, written by hand (no deal.II, no VTK library).
//
// Each VTU holds two pieces. Piece 0 is the film as the surface of revolution
// of the meridian: every sample (R, r, z) becomes a ring of points
// (r cos phi, r sin phi, z), phi = 2 pi j / segments, and neighbouring samples
// are joined by quadrilaterals. At a ring edge the two samples of one radius
// (one per ring) get points of their own and no cell between them, so a jump
// of lambda1 stays a jump. Piece 1 is the rigid disk, a fan of triangles at
// z(A) out to r(A) = a. Lengths in mm, stresses in kPa, fields in MV/m, as in
// the HDF5 file. Point data: R, r, z, lambda1, lambda2, s1, s2, sigma1 and
// sigma2 (true stresses l_i s_i), E, Phi, ring (-1 on the disk), wrinkled (1
// where s2 < 0 or inside the relaxed law's wrinkled zone, past the pre-stretch
// stage as in /summary); NaN on the disk for what it does not have. Field data: TimeValue, stage, load_factor,
// voltage_kV, displacement_mm.
//
// The PVD time is the load parameter: stage - 2 + t, so the pre-stretch runs
// over [-2, -1], the dead load over [-1, 0] and the voltage path over
// [0, number of waypoints] with the path parameter t itself. Where t turns
// back (arc length past a fold) the time goes on by |change of t| so that it
// keeps increasing.
//
// Files: <stem>.pvd and <stem>_vtu/<name>_NNNNNN.vtu, where <stem> is the
// results path without ".h5" and <name> its file name. While the run goes on
// they are <stem>.partial.pvd (rewritten whole after every step, so a killed
// run leaves a readable collection) and <stem>_vtu.partial/; finish() puts them
// in place of an older output of the same name only when the run has ended.

#include <cdea/model/records.h>

#include <cstddef>
#include <string>
#include <vector>

namespace cdea
{
  class ParaViewWriter
  {
  public:
    /// Prepares the partial folder for @p stem (a partial output left by a
    /// killed run of the same name is replaced; anything else of that name
    /// is refused). Throws std::runtime_error naming the path if it cannot
    /// be created.
    ParaViewWriter(const std::string &stem, unsigned int segments);

    /// Writes the VTU of one converged step and the partial PVD. Throws
    /// std::runtime_error naming the file if writing fails, or if the file
    /// would be larger than max_step_file_bytes.
    void write_step(const StepSummary &summary, const StepFields &fields);

    /// Moves the output in place: <stem>_vtu/ and <stem>.pvd, replacing
    /// an older output of that name (a folder, never a link or a file).
    /// Throws std::runtime_error on failure.
    void finish();

    /// Number of steps written.
    unsigned int n_steps() const { return static_cast<unsigned int>(times.size()); }

    /// An older output of the name is there (<stem>.pvd or <stem>_vtu/): a
    /// run cut short leaves it and keeps its own partial output.
    bool older_output_exists() const;

    /// The size of the VTU file of a step of @p samples samples (bytes; at
    /// most about 10 % above it: 423 kB for the 385 kB of prm/paraview.prm's
    /// steps), and the largest allowed: a step's file is
    /// built in memory, so a larger one is refused (write_step() throws, and
    /// the input check refuses it up front: input/validation.cc).
    static double           step_file_bytes(std::size_t samples, unsigned int segments);
    static constexpr double max_step_file_bytes = 256e6;

    /// The PVD time of a step with stage parameter @p tau = stage - 2 + t after
    /// one at @p previous_tau with time @p previous_time (first step:
    /// previous_time NaN).
    static double next_time(double tau, double previous_tau, double previous_time,
                            bool &turned);

  private:
    std::string         stem, name;
    unsigned int        segments;
    /// The partial folder as made (device, inode): one swapped for another
    /// or a link during the run is not written into.
    unsigned long long  folder_device = 0, folder_inode = 0;
    std::vector<double> times;
    double              last_tau = 0.;
    bool                turned   = false;

    std::string folder(bool partial) const;
    void        write_collection(const std::string &path, const std::string &vtu_folder) const;
  };
} // namespace cdea
