#pragma once
// Load terms as plugins, in the manner of ASPECT's plugins: a load term is a
// CellTerm (cell_kernel.h) that declares its own entries of the parameter
// file, reads them, says from them whether it is on, and registers itself at
// the end of its source file, inside namespace cdea, with one line,
//
//   CDEA_REGISTER_LOAD_TERM(WaterTerm, "water", supports_time_runs | ...)
//
// with what it supports beyond the quasi-static FE run. The core lists no
// term: input/ declares and reads every registered term's entries
// (input/parameters_plugins.cc), MembraneModel builds the terms the parameters
// switch on (set_load_terms()), and the checks of input/ refuse a command or
// an option that a term switched on does not support, naming its entry. The
// term files (source/fe/*_term.cc) are linked whole into every program (an
// object library in CMakeLists.txt), so that no registration is dropped.

#include <cdea/base/parameter_declarations.h>
#include <cdea/fe/cell_kernel.h>

#include <memory>
#include <string>
#include <vector>

namespace cdea
{
  struct StepSummary;

  /// What a load term supports beyond the quasi-static FE run by load
  /// stepping (bits of LoadTermPlugin::supports).
  enum LoadTermSupport : unsigned int
  {
    supports_shooting      = 1,  ///< the shooting model has it too (cdea shoot, cdea compare)
    supports_time_runs     = 2,  ///< Time/Enabled = true
    supports_arc_length    = 4,  ///< Solver/Continuation = arc length
    supports_stability     = 8,  ///< Solver/Stability check: the smallest eigenvalue of the tangent
    supports_sensitivities = 16, ///< the exact sensitivities of cdea optimize and cdea fit
    supports_design_map    = 32  ///< the rows of cdea sweep's map
  };

  class LoadTerm : public CellTerm
  {
  public:
    /// The term's entries (ParameterDeclarations::declare_number, ...) and
    /// the entries of others it reads (read_number); none by default.
    static void declare_parameters(ParameterDeclarations &prm) { (void)prm; }

    /// Take the term's settings from @p values, which hold every entry that
    /// declare_parameters() named; throws InputError naming an entry outside
    /// its range. Called on every parameter file, also when the term is off.
    virtual void parse_parameters(const ParameterValues &values) = 0;
    /// Whether the parsed entries switch the term on.
    virtual bool active() const = 0;
    /// The entry that switches it on as the file has it ("Reservoir/Water
    /// load = true"), and the value that switches it off ("false"): the
    /// messages that refuse the term name them.
    virtual std::string switched_on() const = 0;
    virtual std::string off_value() const   = 0;

    /// A line about the term for the start of `cdea run` (empty: none).
    virtual std::string describe() const { return {}; }
    /// Lines (each ending in a newline) about the term in the final state
    /// of a quasi-static run, from its last summary (empty: none).
    virtual std::string describe_state(const StepSummary &summary) const
    {
      (void)summary;
      return {};
    }
  };

  /// A term as CDEA_REGISTER_LOAD_TERM registers it.
  struct LoadTermPlugin
  {
    std::string  name;     ///< for messages and tests
    unsigned int supports; ///< LoadTermSupport bits
    void (*declare_parameters)(ParameterDeclarations &prm);
    std::unique_ptr<LoadTerm> (*create)();
  };

  /// Registers @p plugin; true. Throws std::logic_error if the name is taken.
  bool register_load_term(const LoadTermPlugin &plugin);

  /// The registered terms in their order: by name. Registrations run during
  /// static initialisation in an order the language leaves open; the name
  /// fixes the order in which the terms add into every cell, and so the last
  /// bits of every sum.
  std::vector<LoadTermPlugin> load_term_plugins();

  /// Every registered term's entries (and those it reads), term by term.
  ParameterDeclarations load_term_parameters();

  /// A registered term, parsed from @p values (active or not).
  std::unique_ptr<LoadTerm> parse_load_term(const LoadTermPlugin &plugin,
                                            const ParameterValues &values);

  /// The registered terms that @p values switch on, parsed, in order.
  std::vector<std::unique_ptr<LoadTerm>> make_load_terms(const ParameterValues &values);

  /// The default-constructed term: the factory the registration keeps.
  template <typename Term>
  std::unique_ptr<LoadTerm> create_load_term()
  {
    return std::make_unique<Term>();
  }
} // namespace cdea

/// Registers the load term @p classname under @p name with @p supports
/// (LoadTermSupport bits); one line at the end of the term's source file,
/// inside namespace cdea.
#define CDEA_REGISTER_LOAD_TERM(classname, name, supports)                                   \
  namespace                                                                                  \
  {                                                                                          \
    [[maybe_unused]] const bool classname##_registered = ::cdea::register_load_term(        \
      {name, supports, &classname::declare_parameters, &::cdea::create_load_term<classname>}); \
  }
