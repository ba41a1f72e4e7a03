// The input of `cdea fit` (the data file, subsection Calibration) and the
// displacements of the data points with their Jacobian (DisplacementModel).

#include <cdea/base/file_reading.h>
#include <cdea/base/format.h>
#include <cdea/base/units.h>
#include <cdea/design/fit.h>
#include <cdea/design/fit_data.h>
#include <cdea/fe/load_term.h>
#include <cdea/input/parameters.h>
#include <cdea/input/solver_settings.h>
#include <cdea/input/validation.h>
#include <cdea/model/load_state.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace cdea
{
  namespace
  {
    /// Bounds of the data file: a fit solves every point at every
    /// evaluation, so more points than this are no calibration data.
    constexpr std::size_t max_data_points     = 10000;
    constexpr std::size_t max_data_file_bytes = std::size_t(64) << 20;

    std::string lower_case(std::string s)
    {
      for (char &c : s)
        c = char(std::tolower(static_cast<unsigned char>(c)));
      return s;
    }
  } // namespace

  CalibrationData read_calibration_data(const std::string &file, const unsigned int n_rings,
                                        const double voltage_ceiling)
  {
    // Only a CSV: its lines are quoted in messages.
    const FileRead read = has_extension(file, ".csv") ?
                            read_regular_file(file, max_data_file_bytes) :
                            FileRead{false, "", "the data must be a CSV file whose name ends in "
                                                ".csv"};
    if (!read.ok)
      throw InputError("cannot read data file '" + file + "': " + read.error);
    std::istringstream in(read.bytes);
    return read_calibration_data(in, file, n_rings, voltage_ceiling);
  }

  namespace
  {
    /// The columns of the header line @p fields: every one known, each once,
    /// a voltage per ring and the displacement there.
    std::map<std::string, int> header_columns(const std::vector<std::string> &fields,
                                              const std::string &where, const unsigned int n_rings)
    {
      std::map<std::string, int> column; // name -> index in a line
      for (std::size_t k = 0; k < fields.size(); ++k)
        {
          const std::string &name  = fields[k];
          bool               known = name == "displacement_mm" || name == "weight";
          for (unsigned int r = 1; r <= n_rings; ++r)
            known = known || name == "V" + std::to_string(r) + "_kV";
          if (!known)
            throw InputError(where + ": unknown column '" + printable(name) +
                             "' (expected V1_kV .. V" +
                             std::to_string(n_rings) +
                             "_kV, one per ring of Electrodes/Ring edges (r/a), "
                             "displacement_mm and optionally weight)");
          if (!column.emplace(name, int(k)).second)
            throw InputError(where + ": column '" + name + "' appears twice (columns " +
                             std::to_string(column.at(name) + 1) + " and " +
                             std::to_string(k + 1) + ")");
        }
      for (unsigned int r = 1; r <= n_rings; ++r)
        if (!column.count("V" + std::to_string(r) + "_kV"))
          throw InputError(where + ": no column V" + std::to_string(r) + "_kV (there are " +
                           std::to_string(n_rings) + " rings)");
      if (!column.count("displacement_mm"))
        throw InputError(where + ": no column displacement_mm");
      return column;
    }

    /// One data line @p line (its @p fields) appended to @p data: voltages
    /// from 0 to the film's @p ceiling (V), a displacement |z(A) - z(B)| of
    /// at least 0, a positive weight.
    void add_point(const std::vector<std::string> &fields, const std::string &line,
                   const std::string &where, const std::map<std::string, int> &column,
                   const unsigned int n_rings, const double ceiling, CalibrationData &data)
    {
      const auto place = [&](const std::string &name) {
        return where + ", column " + name;
      };
      const auto value = [&](const std::string &name) {
        return parse_number(fields[column.at(name)], place(name), line);
      };
      std::vector<double> volts;
      for (unsigned int r = 1; r <= n_rings; ++r)
        {
          const std::string name = "V" + std::to_string(r) + "_kV";
          const double      v    = value(name);
          if (v < 0.)
            throw InputError(place(name) + ": a voltage must not be negative, got " +
                             format_number(v));
          if (units::kV.in_si(v) > ceiling)
            throw InputError(place(name) + ": " + format_number(v) +
                             " kV is above the ceiling of " +
                             format_number(units::kV.from_si(ceiling)) +
                             " kV for this film (the field V lam_pre^2 / H in the flat "
                             "pre-stretched film must stay below 10 GV/m)");
          volts.push_back(units::kV.in_si(v));
        }
      const double d = value("displacement_mm");
      if (d < 0.)
        throw InputError(place("displacement_mm") +
                         ": a displacement is the distance |z(A) - z(B)| between disk and "
                         "frame and must not be negative, got " + format_number(d));
      const double w = column.count("weight") ? value("weight") : 1.;
      if (!(w > 0.))
        throw InputError(place("weight") + ": weights must be positive, got " +
                         format_number(w));
      data.voltages.push_back(volts);
      data.displacement.push_back(units::mm.in_si(d));
      data.weight.push_back(w);
    }

  } // namespace

  CalibrationData read_calibration_data(std::istream &in, const std::string &file,
                                        const unsigned int n_rings, const double voltage_ceiling)
  {
    CalibrationData            data;
    std::map<std::string, int> column; // name -> index in a line
    std::size_t                n_columns = 0;
    std::string                line;
    for (unsigned int number = 1; std::getline(in, line); ++number)
      {
        line = csv_content(line, number);
        if (line.find_first_not_of(" \t") == std::string::npos)
          continue;
        const auto        fields = csv_fields(line);
        const std::string where  = file + ", line " + std::to_string(number);
        if (column.empty())
          {
            column    = header_columns(fields, where, n_rings);
            n_columns = fields.size();
            continue;
          }
        if (fields.size() != n_columns)
          throw InputError(where + ": " + std::to_string(fields.size()) +
                           " fields, but the header has " + std::to_string(n_columns));
        if (data.size() == max_data_points)
          throw InputError(where + ": more than " + std::to_string(max_data_points) +
                           " data points");
        add_point(fields, line, where, column, n_rings, voltage_ceiling, data);
      }
    if (column.empty())
      throw InputError(file + ": no header line (the column names V1_kV, ..., displacement_mm)");
    if (data.size() == 0)
      throw InputError(file + ": no data points after the header");
    return data;
  }

  namespace
  {
    /// The film's and the load's parameters a fit may free, by their names
    /// in Calibration/Free parameters.
    const std::vector<std::pair<std::string, ParameterKind>> &scene_parameter_names()
    {
      static const std::vector<std::pair<std::string, ParameterKind>> kinds = {
        {"shear modulus", ParameterKind::shear_modulus},
        {"jlim", ParameterKind::jlim},
        {"permittivity", ParameterKind::permittivity},
        {"mass", ParameterKind::mass},
        {"pre-stretch", ParameterKind::prestretch}};
      return kinds;
    }

    /// An entry without its unit: "Mooney-Rivlin C2 (kPa)" -> "Mooney-Rivlin C2".
    std::string without_unit(const std::string &entry)
    {
      const auto open = entry.rfind(" (");
      return open != std::string::npos && entry.back() == ')' ? entry.substr(0, open) : entry;
    }

    /// The names Calibration/Free parameters accepts under @p law: the
    /// film's constants it depends on, permittivity, mass, pre-stretch and
    /// the law's own constants (their entries of subsection Material).
    std::string allowed_names(const MembraneLaw &law)
    {
      std::string list = "shear modulus";
      if (law.depends_on(LawParameter::jlim))
        list += ", Jlim";
      list += ", permittivity, mass, pre-stretch";
      for (const LawConstant &c : law.own_constants())
        list += ", " + c.entry;
      return list;
    }

    /// The parameter @p key (lower case) names under @p law; InputError
    /// naming the entry @p name and what this law allows.
    SceneParameter free_parameter(const std::string &key, const std::string &name,
                                  const MembraneLaw &law, const std::string &model)
    {
      const std::string under =
        model == LawSettings().model ? "" : " with Material/Model = " + model;
      for (const auto &[text, kind] : scene_parameter_names())
        if (key == text)
          {
            // Under a law without the Gent limit the displacement does not
            // depend on Jlim: a free Jlim would make the fit singular.
            if (kind == ParameterKind::jlim && !law.depends_on(LawParameter::jlim))
              throw InputError(name + ": 'jlim': Material/Model = " + model +
                               " has no Jlim, the displacements do not depend on it (any of " +
                               allowed_names(law) + ")");
            return {kind, 0};
          }
      for (const LawConstant &c : law.own_constants())
        if (key == lower_case(c.entry) || key == lower_case(without_unit(c.entry)))
          return {ParameterKind::law_constant, 0, c.entry};
      throw InputError(name + ": '" + key + "' is not a parameter that can be fitted" + under +
                       " (any of " + allowed_names(law) + ")");
    }
  } // namespace

  FitSettings fit_settings(const Parameters &p)
  {
    require_quasi_static_elastic(p, "fit");
    FitSettings s = free_parameter_settings(p);
    if (p.wrinkling.model != WrinklingModel::check)
      throw InputError("cdea fit supports Wrinkling/Model = check only (the displacement of "
                       "the actuator under its dead load)");
    require_load_term_support(p, supports_sensitivities, "fit",
                              "it fits the displacement of the actuator under its dead load");
    return s;
  }

  FitSettings free_parameter_settings(const Parameters &p)
  {
    const std::string name  = "Calibration/Free parameters";
    const auto        law   = p.scene().law();
    FitSettings       s;
    for (const std::string &item : split_list(p.calibration.free_parameters_text, ','))
      {
        const auto           fields = csv_fields(item);
        const std::string    key    = lower_case(fields.empty() ? "" : fields[0]);
        const SceneParameter free   = free_parameter(key, name, *law, p.material_law.model);
        for (const auto &f : s.free)
          if (f.kind == free.kind && f.entry == free.entry)
            throw InputError(name + ": '" + key + "' is given twice");
        s.free.push_back(free);
      }
    if (s.free.empty())
      throw InputError(name + ": no parameter given (any of " + allowed_names(*law) + ")");
    s.max_iterations = p.calibration.max_iterations;
    s.tolerance      = p.calibration.tolerance;
    return s;
  }

  void require_enough_points(const CalibrationData &data, const FitSettings &settings,
                             const std::string &name)
  {
    if (data.size() < settings.free.size())
      throw InputError(name + ": " + std::to_string(data.size()) + " data points for " +
                       std::to_string(settings.free.size()) +
                       " free parameters (Calibration/Free parameters): give at least as "
                       "many points as parameters");
  }

  std::string value_text(const SceneParameter &p, const double value)
  {
    switch (p.kind)
      {
        case ParameterKind::shear_modulus:
          return format_number(units::kPa.from_si(value)) + " kPa";
        case ParameterKind::mass:
          return format_number(units::g.from_si(value)) + " g";
        case ParameterKind::permittivity:
          return format_number(value) + " F/m";
        default:
          return format_number(value);
      }
  }

  std::string label(const SceneParameter &p)
  {
    switch (p.kind)
      {
        case ParameterKind::shear_modulus:
          return "shear modulus";
        case ParameterKind::jlim:
          return "Jlim";
        case ParameterKind::permittivity:
          return "permittivity";
        case ParameterKind::mass:
          return "mass";
        case ParameterKind::prestretch:
          return "pre-stretch";
        default:
          return p.name();
      }
  }

  Calibrated calibrate(const Parameters &p, const Scene &base, const CalibrationData &data,
                       const FitSettings &settings,
                       const std::function<void(unsigned int, double, const std::vector<double> &)>
                         &progress)
  {
    DisplacementModel model(base, data, settings.free, fe_discretization(p), newton_settings(p),
                            study_stepping_settings(p));
    Calibrated c;
    c.result = fit(base, data, settings, model, progress);
    if (c.result.fitted.size() > 0)
      {
        std::vector<std::vector<double>> v;
        std::vector<double>              d;
        model.curve(c.result.values, 8, v, d);
        c.curve_voltages     = std::move(v);
        c.curve_displacement = std::move(d);
      }
    c.solves = model.solves();
    c.ramps  = model.ramps();
    return c;
  }

  Scene scene_with(const Scene &base, const std::vector<SceneParameter> &free,
                   const std::vector<double> &values)
  {
    Scene s = base;
    for (std::size_t j = 0; j < free.size(); ++j)
      s = with_parameter(s, free[j], values[j]);
    return s;
  }

  DisplacementModel::DisplacementModel(const Scene &base_in, const CalibrationData &data_in,
                                       const std::vector<SceneParameter> &free_in,
                                       const FeDiscretization &disc,
                                       const NewtonSettings   &newton_in,
                                       const SteppingSettings &stepping_in)
    : base(base_in)
    , data(data_in)
    , free(free_in)
    , discretization(disc)
    , newton(newton_in)
    , stepping(stepping_in)
    , states(data_in.size())
    , state_derivatives(data_in.size())
  {}

  DisplacementModel::~DisplacementModel() = default;

  MembraneModel &DisplacementModel::model_for(const std::vector<double> &values)
  {
    if (!model || values != model_values)
      {
        scene        = scene_with(base, free, values);
        model        = std::make_unique<MembraneModel>(scene, discretization, newton);
        model_values = values;
      }
    return *model;
  }

  LoadState DisplacementModel::load_of(const unsigned int point) const
  {
    return full_load(scene, data.voltages[point]);
  }

  bool DisplacementModel::ramp(const unsigned int point, std::string *message, const int via)
  {
    ++ramps_;
    Scene                            ramp_scene = scene;
    std::vector<std::vector<double>> waypoints;
    if (via >= 0)
      waypoints.push_back(data.voltages[unsigned(via)]);
    waypoints.push_back(data.voltages[point]);
    ramp_scene.path = VoltagePath(waypoints);
    LoadStepper     stepper(ramp_scene, *model, stepping);
    const RunResult run = stepper.run();
    solves_ += run.solves;
    if (!run.completed && message)
      *message = run.message;
    return run.completed;
  }

  std::string DisplacementModel::point_text(const unsigned int point) const
  {
    return "data point " + std::to_string(point + 1) + " (" + format_kV(data.voltages[point]) +
           ")";
  }

  void DisplacementModel::keep(const unsigned int point, const StateSensitivity &at,
                               Eigen::VectorXd &d, Eigen::MatrixXd *jacobian)
  {
    d[point] = at.displacement();
    if (jacobian)
      jacobian->row(point) = at.d_displacement().transpose();
    states[point]            = model->state();
    state_derivatives[point] = at.state_derivative();
  }

  bool DisplacementModel::evaluate(const std::vector<double> &values, Eigen::VectorXd &d,
                                   Eigen::MatrixXd *jacobian, std::string *message)
  {
    MembraneModel &m = model_for(values);
    const unsigned int M = data.size();
    d.resize(M);
    if (jacobian)
      jacobian->resize(M, free.size());
    const bool continued = state_values.size() == values.size();
    Eigen::VectorXd dp(values.size());
    for (std::size_t j = 0; continued && j < values.size(); ++j)
      dp[j] = values[j] - state_values[j];
    std::vector<std::pair<unsigned int, std::string>> missed; // at the start: point, why
    for (unsigned int i = 0; i < M; ++i)
      {
        // From the point's own last state by the tangent predictor; a ramp
        // from zero if that fails or lands beyond a fold.
        bool ok = false;
        if (continued)
          {
            ModelState guess = predicted_state(states[i], state_derivatives[i], dp);
            guess.load       = load_of(i);
            m.set_state(guess);
            ok = m.solve(guess.load).converged;
            ++solves_;
          }
        std::unique_ptr<StateSensitivity> at;
        if (ok)
          at = std::make_unique<StateSensitivity>(m, free);
        if (!ok || !at->stable())
          {
            std::string why;
            if (!ramp(i, &why))
              {
                if (continued)
                  {
                    if (message)
                      *message = point_text(i) + " cannot be reached from zero voltage: " + why;
                    return false;
                  }
                missed.emplace_back(i, why);
                continue;
              }
            at = std::make_unique<StateSensitivity>(m, free);
          }
        keep(i, *at, d, jacobian);
      }
    if (!missed.empty() && !reach_along_the_data(missed, values, d, jacobian, message))
      return false;
    state_values = values;
    return true;
  }

  bool DisplacementModel::reach_along_the_data(
    const std::vector<std::pair<unsigned int, std::string>> &missed,
    const std::vector<double> &values, Eigen::VectorXd &d, Eigen::MatrixXd *jacobian,
    std::string *message)
  {
    // The start: a point the ramp from zero misses (beyond a fold of the
    // proportional path) is continued from the nearest point that was
    // reached, as an experiment steps through its data.
    std::vector<bool> reached(data.size(), true);
    for (const auto &[point, why] : missed)
      reached[point] = false;
    for (const auto &[point, why] : missed)
      {
        int    via  = -1;
        double best = HUGE_VAL;
        for (unsigned int j = 0; j < data.size(); ++j)
          if (reached[j])
            {
              double distance = 0.;
              for (std::size_t r = 0; r < data.voltages[j].size(); ++r)
                distance += std::pow(data.voltages[j][r] - data.voltages[point][r], 2);
              if (distance < best)
                best = distance, via = int(j);
            }
        std::string from_via;
        if (via >= 0 && ramp(point, &from_via, via))
          {
            keep(point, StateSensitivity(*model, free), d, jacobian);
            reached[point] = true;
            continue;
          }
        if (message)
          *message = point_text(point) + " cannot be reached at " + values_text(values) +
                     ": from zero voltage: " + why +
                     (via >= 0 ? "; nor from " + point_text(unsigned(via)) + ", the nearest " +
                                   "point reached: " + from_via :
                                 std::string("; no other point was reached either"));
        return false;
      }
    return true;
  }

  std::string DisplacementModel::values_text(const std::vector<double> &values) const
  {
    std::string text;
    for (std::size_t j = 0; j < free.size(); ++j)
      text += (j ? ", " : "") + label(free[j]) + " " + value_text(free[j], values[j]);
    return text;
  }

  void DisplacementModel::curve(const std::vector<double> &values, const unsigned int steps,
                                std::vector<std::vector<double>> &voltages,
                                std::vector<double>              &displacement)
  {
    voltages.clear();
    displacement.clear();
    MembraneModel &m = model_for(values);
    if (data.size() == 0 || !ramp(0, nullptr))
      return;
    voltages.push_back(data.voltages[0]);
    displacement.push_back(m.displacement());
    for (unsigned int i = 1; i < data.size(); ++i)
      for (unsigned int k = 1; k <= steps; ++k)
        {
          LoadState load = load_of(i);
          for (std::size_t r = 0; r < load.voltages.size(); ++r)
            load.voltages[r] = data.voltages[i - 1][r] +
                               (data.voltages[i][r] - data.voltages[i - 1][r]) * k / steps;
          ++solves_;
          if (!m.solve(load).converged)
            return; // the curve ends where continuation cannot go on
          voltages.push_back(load.voltages);
          displacement.push_back(m.displacement());
        }
  }
} // namespace cdea
