// The specimen entries of subsection Calibration (input/specimen_entries.h),
// a subsection of their own after the Frequency sweep (position 200).

#include <cdea/input/parameters.h>
#include <cdea/input/specimen_entries.h>

namespace cdea
{
  void SpecimenEntries::declare_entries(ParameterDeclarations &prm)
  {
    prm.enter_subsection("Calibration");
    prm.add_text("Specimen test", "uniaxial",
                 "The test of raw machine data (time_s, displacement_mm, force_N): "
                 "uniaxial, equibiaxial or pure shear.");
    prm.add_number("Specimen gauge length (mm)", "0",
                   "Undeformed length between the grips: stretch = 1 + displacement / gauge "
                   "length of raw machine data (0: not given).");
    prm.add_number("Specimen width (mm)", "0",
                   "Undeformed width of the loaded cross-section of raw machine data (0: not "
                   "given).");
    prm.add_number("Specimen thickness (mm)", "0",
                   "Undeformed thickness: nominal stress = force / (width thickness) of raw "
                   "machine data (0: not given).");
    prm.leave_subsection();
  }

  void SpecimenEntries::declare(ParameterDeclarations &prm)
  {
    ParameterDeclarations entries;
    declare_entries(entries);
    prm.append(entries, values);
  }

  CDEA_REGISTER_OWN_SUBSECTION(specimen, SpecimenEntries, 200)
} // namespace cdea
