#pragma once
// Load terms as plugins, in the manner of ASPECT's plugins: a load term is a
// CellTerm (cell_kernel.h) that declares its own entries of the parameter
// file, is created from their values (a constructor that parses them), says
// from them whether it is on, and registers itself at the end of its source
// file, inside namespace cdea, with one line,
//
//   CDEA_REGISTER_PLUGIN(LoadTerms, WaterTerm, "water", supports_time_runs | ..., "description")
//
// with what it supports beyond the quasi-static FE run (a PluginList,
// base/plugin_list.h, as the laws and the postprocessors). The core lists no
// term: input/ declares and reads every registered term's entries
// (input/parameters_plugins.cc), MembraneModel builds the terms the parameters
// switch on (set_load_terms()), and the checks of input/ refuse a command or
// an option that a term switched on does not support, naming its entry. The
// term files (source/fe/*_term.cc) are linked whole into every program (an
// object library in CMakeLists.txt), so that no registration is dropped.

#include <cdea/base/plugin_list.h>
#include <cdea/fe/cell_kernel.h>
#include <cdea/model/transient_model.h>

#include <memory>
#include <string>
#include <vector>

namespace cdea
{
  struct StepSummary;

  /// What a load term supports beyond the quasi-static FE run by load
  /// stepping (the flags of a LoadTerms plugin).
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
    /// The term's entries (ParameterDeclarations::add_number, ...) and the
    /// entries of others it reads (read_number); none by default.
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

    /// The liquid column the term's load moves with the enclosed volume (the
    /// water load's), whose inertia time runs and the small-signal dynamics
    /// take (transient_model.h); none by default.
    virtual LiquidColumn liquid_column() const { return {}; }

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

  /// The registered terms, made from the values of their entries; their
  /// flags are LoadTermSupport bits. Their order (by name) fixes the order in
  /// which the terms add into every cell, and so the last bits of every sum.
  using LoadTerms = PluginList<LoadTerm, ParameterValues>;

  /// The registered terms that @p values switch on, parsed, in order.
  std::vector<std::unique_ptr<LoadTerm>> make_load_terms(const ParameterValues &values);
} // namespace cdea
