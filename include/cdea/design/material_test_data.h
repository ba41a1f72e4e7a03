#pragma once
// Material-test data (doc/materials.md, "The material-test model"): the
// history of one homogeneous test as a CSV file whose header says its kind,
//
//   time_s, uniaxial_stretch, nominal_stress_kPa      uniaxial tension
//   time_s, equibiaxial_stretch, nominal_stress_kPa   equibiaxial tension
//   time_s, pure_shear_stretch, nominal_stress_kPa    pure shear (planar tension)
//   time_s, displacement_mm, force_N                  a machine's raw columns
//
// each with an optional weight column, in any order ('#' comments; the CSV
// reading of design/fit_data.h). The stretch is the loaded direction's from
// the unstressed state; the nominal stress is the force over the undeformed
// cross-section. Raw columns need the specimen (its test, gauge length,
// width and thickness): stretch = 1 + displacement / gauge length, nominal
// stress = force / (width thickness).

#include <cdea/material/material_point.h>

#include <istream>
#include <string>
#include <vector>

namespace cdea
{
  class ParameterDeclarations;
  class ParameterValues;
  struct Parameters;

  /// The specimen of raw machine columns (SI); sizes 0: not given.
  struct TestSpecimen
  {
    TestKind kind         = TestKind::uniaxial;
    double   gauge_length = 0.; ///< m, undeformed, between the grips
    double   width        = 0.; ///< m, undeformed, of the loaded cross-section
    double   thickness    = 0.; ///< m, undeformed
  };

  /// The specimen's entries of subsection Calibration, declared as a
  /// plugin's (base/parameter_declarations.h): "Specimen test" (uniaxial,
  /// equibiaxial or pure shear), "Specimen gauge length (mm)", "Specimen
  /// width (mm)", "Specimen thickness (mm)" (0: not given).
  void declare_specimen_parameters(ParameterDeclarations &prm);
  /// The specimen from those entries, checked: InputError naming the entry
  /// and what is allowed (a test name, sizes from 0 to 1e4 mm).
  TestSpecimen parse_specimen(const ParameterValues &values);
  /// The specimen of a parameter file: those entries, registered as a
  /// subsection of its own (Parameters::subsection()), parsed.
  TestSpecimen test_specimen(const Parameters &p);

  /// One test's history as measured.
  struct MaterialTestData
  {
    std::string               name;    ///< the file, for messages and tables
    StretchHistory            history; ///< kind, sample times (s), stretches
    std::vector<double>       stress;  ///< nominal stress (Pa) at every sample
    std::vector<double>       weight;  ///< of every sample (1 without the column)
    std::vector<unsigned int> lines;   ///< the file's line of every sample
    bool                      raw = false; ///< machine columns through a specimen
    std::size_t               size() const { return stress.size(); }
  };

  /// Whether CSV text's header line (the first that is not blank or a
  /// comment) names a material test: a column uniaxial_stretch,
  /// equibiaxial_stretch, pure_shear_stretch or force_N.
  bool is_material_test(std::istream &in);
  /// The same for file @p file (InputError if it cannot be read).
  bool is_material_test(const std::string &file);

  /// The file's weight in a joint fit: a comment line "# weight W" (W a
  /// number above 0) above the header line; 1 without. InputError naming
  /// the file and line for a bad or second weight line.
  double material_test_weight(std::istream &in, const std::string &file);
  double material_test_weight(const std::string &file);

  /// Reads one test (a regular file of at most 64 MB, at most 1e5 rows):
  /// times from 0, increasing strictly; stretches at least 1 (tension;
  /// raw: displacements from 0); stresses any number; weights above 0.
  /// InputError naming the file, line and column: an unknown column, a
  /// kind's column mixed with another kind's, a missing column, a bad value,
  /// no rows; raw columns without @p specimen sizes.
  MaterialTestData read_material_test(const std::string &file, const TestSpecimen &specimen = {});
  MaterialTestData read_material_test(std::istream &in, const std::string &name,
                                      const TestSpecimen &specimen = {});
} // namespace cdea
