// The input of `cdea fit` (the data file, subsection Calibration) and the
// displacements of the data points with their Jacobian (DisplacementModel).

#include <cdea/base/format.h>
#include <cdea/design/fit.h>
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
    /// Fields of one CSV line, blanks around each removed; a ',' at the end
    /// of the line ends in an empty field.
    std::vector<std::string> fields_of(const std::string &line)
    {
      std::vector<std::string> fields;
      for (const std::string &field : split_list(line, ','))
        {
          std::size_t b = 0, e = field.size();
          while (b < e && std::isspace(static_cast<unsigned char>(field[b])))
            ++b;
          while (e > b && std::isspace(static_cast<unsigned char>(field[e - 1])))
            --e;
          fields.push_back(field.substr(b, e - b));
        }
      if (!line.empty() && line.back() == ',')
        fields.emplace_back();
      return fields;
    }

    std::string lower_case(std::string s)
    {
      for (char &c : s)
        c = char(std::tolower(static_cast<unsigned char>(c)));
      return s;
    }
  } // namespace

  CalibrationData read_calibration_data(const std::string &file, const unsigned int n_rings)
  {
    std::ifstream in(file);
    if (!in)
      throw InputError("cannot read data file '" + file + "'");
    return read_calibration_data(in, file, n_rings);
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
            throw InputError(where + ": unknown column '" + name + "' (expected V1_kV .. V" +
                             std::to_string(n_rings) +
                             "_kV, one per ring of Electrodes/Ring edges (r/a), "
                             "displacement_mm and optionally weight)");
          if (!column.emplace(name, int(k)).second)
            throw InputError(where + ": column '" + name + "' appears twice");
        }
      for (unsigned int r = 1; r <= n_rings; ++r)
        if (!column.count("V" + std::to_string(r) + "_kV"))
          throw InputError(where + ": no column V" + std::to_string(r) + "_kV (there are " +
                           std::to_string(n_rings) + " rings)");
      if (!column.count("displacement_mm"))
        throw InputError(where + ": no column displacement_mm");
      return column;
    }

    /// One data line @p line (its @p fields) appended to @p data.
    void add_point(const std::vector<std::string> &fields, const std::string &line,
                   const std::string &where, const std::map<std::string, int> &column,
                   const unsigned int n_rings, CalibrationData &data)
    {
      const auto value = [&](const std::string &name) {
        return parse_number(fields[column.at(name)], where + ", column " + name, line);
      };
      std::vector<double> volts;
      for (unsigned int r = 1; r <= n_rings; ++r)
        {
          const std::string name = "V" + std::to_string(r) + "_kV";
          const double      v    = value(name);
          if (v < 0.)
            throw InputError(where + ", column " + name +
                             ": a voltage must not be negative, got " + format_number(v));
          volts.push_back(v * 1e3);
        }
      const double d = value("displacement_mm");
      const double w = column.count("weight") ? value("weight") : 1.;
      if (!(w > 0.))
        throw InputError(where + ", column weight: weights must be positive, got " +
                         format_number(w));
      data.voltages.push_back(volts);
      data.displacement.push_back(d * 1e-3);
      data.weight.push_back(w);
    }
  } // namespace

  CalibrationData read_calibration_data(std::istream &in, const std::string &file,
                                        const unsigned int n_rings)
  {
    CalibrationData            data;
    std::map<std::string, int> column; // name -> index in a line
    std::size_t                n_columns = 0;
    std::string                line;
    for (unsigned int number = 1; std::getline(in, line); ++number)
      {
        if (const auto hash = line.find('#'); hash != std::string::npos)
          line.erase(hash);
        if (!line.empty() && line.back() == '\r')
          line.pop_back();
        if (line.find_first_not_of(" \t") == std::string::npos)
          continue;
        const auto        fields = fields_of(line);
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
        add_point(fields, line, where, column, n_rings, data);
      }
    if (column.empty())
      throw InputError(file + ": no header line (the column names V1_kV, ..., displacement_mm)");
    if (data.size() == 0)
      throw InputError(file + ": no data points after the header");
    return data;
  }

  FitSettings fit_settings(const Parameters &p)
  {
    require_quasi_static_elastic(p, "fit");
    const std::string name = "Calibration/Free parameters";
    static const std::pair<const char *, ParameterKind> kinds[] = {
      {"shear modulus", ParameterKind::shear_modulus},
      {"jlim", ParameterKind::jlim},
      {"permittivity", ParameterKind::permittivity},
      {"mass", ParameterKind::mass},
      {"pre-stretch", ParameterKind::prestretch}};
    FitSettings s;
    for (const std::string &item : split_list(p.calibration.free_parameters_text, ','))
      {
        const auto fields = fields_of(item);
        const std::string key = lower_case(fields.empty() ? "" : fields[0]);
        const auto        hit = std::find_if(std::begin(kinds), std::end(kinds),
                                      [&](const auto &k) { return key == k.first; });
        if (hit == std::end(kinds))
          throw InputError(name + ": '" + key + "' is not a parameter that can be fitted (any "
                           "of shear modulus, Jlim, permittivity, mass, pre-stretch)");
        for (const auto &f : s.free)
          if (f.kind == hit->second)
            throw InputError(name + ": '" + key + "' is given twice");
        s.free.push_back({hit->second, 0});
      }
    if (s.free.empty())
      throw InputError(name + ": no parameter given (any of shear modulus, Jlim, permittivity, "
                       "mass, pre-stretch)");
    s.max_iterations = p.calibration.max_iterations;
    s.tolerance      = p.calibration.tolerance;
    if (p.wrinkling.model != WrinklingModel::check)
      throw InputError("cdea fit supports Wrinkling/Model = check only (the displacement of "
                       "the actuator under its dead load)");
    require_load_term_support(p, supports_sensitivities, "fit",
                              "it fits the displacement of the actuator under its dead load");
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
        for (std::size_t k = 0; k < v.size(); ++k)
          {
            std::vector<double> kV;
            for (const double x : v[k])
              kV.push_back(x * 1e-3);
            c.curve_kV.push_back(kV);
            c.curve_mm.push_back(d[k] * 1e3);
          }
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

  bool DisplacementModel::ramp(const unsigned int point, std::string *message)
  {
    ++ramps_;
    Scene ramp_scene = scene;
    ramp_scene.path  = VoltagePath(std::vector<std::vector<double>>{data.voltages[point]});
    LoadStepper     stepper(ramp_scene, *model, stepping);
    const RunResult run = stepper.run();
    solves_ += run.solves;
    if (!run.completed && message)
      *message = "data point " + std::to_string(point + 1) + " (" +
                 format_kV(data.voltages[point]) + ") cannot be reached from zero voltage: " +
                 run.message;
    return run.completed;
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
            if (!ramp(i, message))
              return false;
            at = std::make_unique<StateSensitivity>(m, free);
          }
        d[i] = at->displacement();
        if (jacobian)
          jacobian->row(i) = at->d_displacement().transpose();
        states[i]            = m.state();
        state_derivatives[i] = at->state_derivative();
      }
    state_values = values;
    return true;
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
