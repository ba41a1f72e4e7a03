// The uncertain constants of subsection Uncertainty (analysis/uncertainty.h):
// parsed and checked against the scene's law, the covariance of a fit's file,
// the samples of Monte-Carlo and their statistics.

#include <cdea/analysis/uncertainty.h>
#include <cdea/base/file_reading.h>
#include <cdea/base/format.h>
#include <cdea/base/text.h>
#include <cdea/base/units.h>
#include <cdea/material/membrane_law.h>
#include <cdea/output/hdf5_support.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <random>

namespace cdea
{
  double UncertainConstants::linear_sd(const Eigen::VectorXd &g) const
  {
    return std::sqrt(std::max(0., g.dot(covariance * g)));
  }

  namespace
  {
    const std::string section = "Uncertainty/";

    std::string lower(std::string text)
    {
      std::transform(text.begin(), text.end(), text.begin(),
                     [](const unsigned char c) { return char(std::tolower(c)); });
      return text;
    }

    /// A constant that may be uncertain: its names (lower case; as
    /// Calibration/Free parameters names it, its entry of the parameter file,
    /// and the fit file's SceneParameter::name()) and the factor from its
    /// entry's unit to the sensitivities' unit.
    struct Candidate
    {
      std::string    name, entry, file_name;
      SceneParameter parameter;
      double         to_si = 1.;
    };

    /// An entry without its unit: "Mooney-Rivlin C2 (kPa)" -> "Mooney-Rivlin C2".
    std::string without_unit(const std::string &entry)
    {
      const auto open = entry.rfind(" (");
      return open != std::string::npos && entry.back() == ')' ? entry.substr(0, open) : entry;
    }

    /// The constants of @p law's scene that may be uncertain, as
    /// Calibration/Free parameters names them.
    std::vector<Candidate> candidates(const MembraneLaw &law)
    {
      std::vector<Candidate> list = {
        {"shear modulus", "shear modulus (kpa)", "", {ParameterKind::shear_modulus},
         units::kPa.to_si},
        {"jlim", "jlim", "", {ParameterKind::jlim}, 1.},
        {"permittivity", "permittivity (f/m)", "", {ParameterKind::permittivity}, 1.},
        {"mass", "mass (g)", "", {ParameterKind::mass}, units::g.to_si},
        {"pre-stretch", "prestretch", "", {ParameterKind::prestretch}, 1.}};
      if (!law.depends_on(LawParameter::jlim))
        list.erase(list.begin() + 1);
      for (const LawConstant &c : law.own_constants())
        list.push_back({lower(without_unit(c.entry)), lower(c.entry), "",
                        {ParameterKind::law_constant, 0, c.entry}, 1.});
      for (Candidate &c : list)
        c.file_name = lower(c.parameter.name());
      return list;
    }

    std::string allowed(const std::vector<Candidate> &list)
    {
      std::string text;
      for (const Candidate &c : list)
        text += (text.empty() ? "" : ", ") + c.name;
      return text;
    }

    /// The candidate named @p key (the entry's name, with or without its
    /// unit, or the fit file's name); InputError naming @p entry otherwise.
    const Candidate &find(const std::vector<Candidate> &list, const std::string &key,
                          const std::string &entry)
    {
      const std::string k = lower(trim_blanks(key));
      for (const Candidate &c : list)
        if (k == c.name || k == c.entry || k == c.file_name)
          return c;
      throw InputError(entry + ": '" + trim_blanks(key) +
                       "' is not a constant of this scene that can be uncertain (any of " +
                       allowed(list) + ")");
    }

    /// InputError unless @p r (a correlation matrix) is positive semidefinite.
    void require_semidefinite(const Eigen::MatrixXd &r, const std::string &entry)
    {
      if (r.size() == 0)
        return;
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(r, Eigen::EigenvaluesOnly);
      const double smallest = eigen.eigenvalues().minCoeff();
      if (!(smallest >= -1e-10))
        throw InputError(entry + ": the correlation matrix is not positive semidefinite "
                                 "(its smallest eigenvalue is " +
                         format_number(smallest, 4) +
                         "): no set of constants can be correlated so");
    }

    /// "NAME: VALUE" split at its last ':'; InputError naming @p entry.
    std::pair<std::string, std::string> named_value(const std::string &item,
                                                    const std::string &entry,
                                                    const std::string &form)
    {
      const auto colon = item.rfind(':');
      if (colon == std::string::npos || trim_blanks(item.substr(0, colon)).empty() ||
          trim_blanks(item.substr(colon + 1)).empty())
        throw InputError(entry + ": '" + trim_blanks(item) + "' is not of the form " + form);
      return {trim_blanks(item.substr(0, colon)), trim_blanks(item.substr(colon + 1))};
    }

    /// Standard deviations and Correlations into @p c.
    void explicit_constants(const UncertaintyEntries &e, const Scene &scene,
                            const std::vector<Candidate> &list, UncertainConstants &c)
    {
      const std::string   entry = section + "Standard deviations";
      std::vector<double> sd;
      for (const std::string &item : split_list(e.standard_deviations_text, ','))
        {
          const auto [name, text] = named_value(item, entry, "NAME: VALUE or NAME: VALUE%");
          const Candidate &k      = find(list, name, entry);
          for (const SceneParameter &p : c.parameters)
            if (p.kind == k.parameter.kind && p.entry == k.parameter.entry)
              throw InputError(entry + ": '" + name + "' is given twice");
          const bool   relative = text.back() == '%';
          const double value    = parse_number(
            trim_blanks(relative ? text.substr(0, text.size() - 1) : text), entry, text);
          if (value < 0.)
            throw InputError(entry + ": '" + name + "': a standard deviation must be zero or "
                                                    "positive, got " + text);
          c.parameters.push_back(k.parameter);
          c.names.push_back(name);
          sd.push_back(relative ? value / 100. * std::abs(parameter_value(scene, k.parameter)) :
                                  value * k.to_si);
        }
      const std::size_t n = sd.size();
      Eigen::MatrixXd   r = Eigen::MatrixXd::Identity(n, n);
      const std::string pairs = section + "Correlations";
      for (const std::string &item : split_list(e.correlations_text, ';'))
        {
          const auto [names, text] = named_value(item, pairs, "NAME, NAME: VALUE");
          const auto two           = split_list(names, ',');
          if (two.size() != 2)
            throw InputError(pairs + ": '" + trim_blanks(item) +
                             "' does not name two constants (NAME, NAME: VALUE)");
          std::size_t index[2];
          for (int s = 0; s < 2; ++s)
            {
              const Candidate &k = find(list, two[s], pairs);
              index[s]           = n;
              for (std::size_t j = 0; j < n; ++j)
                if (c.parameters[j].kind == k.parameter.kind &&
                    c.parameters[j].entry == k.parameter.entry)
                  index[s] = j;
              if (index[s] == n)
                throw InputError(pairs + ": '" + trim_blanks(two[s]) +
                                 "' has no standard deviation (Uncertainty/Standard deviations)");
            }
          const double rho = parse_number(text, pairs, text);
          if (index[0] == index[1] || !(std::abs(rho) <= 1.))
            throw InputError(pairs + ": '" + trim_blanks(item) +
                             "': a correlation is between two different constants and lies "
                             "between -1 and 1");
          if (r(index[0], index[1]) != 0.)
            throw InputError(pairs + ": the pair of '" + trim_blanks(item) + "' is given twice");
          r(index[0], index[1]) = r(index[1], index[0]) = rho;
        }
      require_semidefinite(r, pairs);
      const Eigen::VectorXd s = Eigen::Map<const Eigen::VectorXd>(sd.data(), Eigen::Index(n));
      c.covariance            = s.asDiagonal() * r * s.asDiagonal();
    }

    /// The attribute free_parameters ("a; b") and the dataset /covariance
    /// of the fit file's image @p bytes; false if either is missing.
    bool read_fit_covariance(std::string &bytes, std::vector<std::string> &names,
                             Eigen::MatrixXd &covariance)
    {
      hdf5::ErrorPrintingOff quiet;
      const hdf5::Handle     fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
      if (fapl < 0 || H5Pset_fapl_core(fapl, 1 << 16, false) < 0 ||
          H5Pset_file_image(fapl, bytes.data(), bytes.size()) < 0)
        return false;
      static unsigned long long count = 0;
      const std::string image = "cdea-covariance-image-" + std::to_string(++count);
      const hdf5::Handle file(H5Fopen(image.c_str(), H5F_ACC_RDONLY, fapl), H5Fclose);
      if (file < 0)
        return false;
      const hdf5::Handle attribute(H5Aopen(file, "free_parameters", H5P_DEFAULT), H5Aclose);
      const hdf5::Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
      char              *text = nullptr;
      // As the writer stores text: variable length, UTF-8.
      if (attribute < 0 || type < 0 || H5Tset_size(type, H5T_VARIABLE) < 0 ||
          H5Tset_cset(type, H5T_CSET_UTF8) < 0 ||
          H5Aread(attribute, type, &text) < 0 || text == nullptr)
        return false;
      names = split_list(text, ';');
      H5free_memory(text);
      const hdf5::Handle set(H5Dopen2(file, "/covariance", H5P_DEFAULT), H5Dclose);
      if (set < 0)
        return false;
      const hdf5::Handle space(H5Dget_space(set), H5Sclose);
      hsize_t            dims[2] = {0, 0};
      if (space < 0 || H5Sget_simple_extent_ndims(space) != 2 ||
          H5Sget_simple_extent_dims(space, dims, nullptr) != 2 || dims[0] != names.size() ||
          dims[1] != names.size())
        return false;
      // Row-major in the file, as Eigen's column-major transpose: the matrix is symmetric.
      covariance.resize(Eigen::Index(dims[0]), Eigen::Index(dims[1]));
      return H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, covariance.data()) >=
             0;
    }

    /// The constants and covariance of a fit's <Base name>_fit.h5.
    void file_constants(const std::string &path, const std::vector<Candidate> &list,
                        UncertainConstants &c)
    {
      const std::string entry = section + "Covariance file";
      const FileRead    read  = read_regular_file(path, std::size_t(256) << 20);
      if (!read.ok)
        throw MissingFileError(entry + " '" + path + "': " + read.error);
      std::string     bytes = read.bytes;
      Eigen::MatrixXd covariance;
      if (!read_fit_covariance(bytes, c.names, covariance))
        throw InputError(entry + " '" + path +
                         "' is no fit file with a covariance (the free_parameters attribute "
                         "and the covariance dataset of a <Base name>_fit.h5 of cdea fit)");
      for (std::size_t j = 0; j < c.names.size(); ++j)
        {
          c.names[j] = trim_blanks(c.names[j]);
          c.parameters.push_back(find(list, c.names[j], entry + " '" + path + "'").parameter);
          if (!std::isfinite(covariance(Eigen::Index(j), Eigen::Index(j))))
            throw InputError(entry + " '" + path + "': the fit determined no variance of '" +
                             c.names[j] + "' (the data do not identify it)");
        }
      const Eigen::VectorXd d = covariance.diagonal().cwiseSqrt();
      Eigen::MatrixXd       r = covariance;
      for (Eigen::Index i = 0; i < r.rows(); ++i)
        for (Eigen::Index j = 0; j < r.cols(); ++j)
          r(i, j) = d[i] > 0. && d[j] > 0. ? covariance(i, j) / (d[i] * d[j]) : (i == j ? 1. : 0.);
      if (!r.allFinite())
        throw InputError(entry + " '" + path + "': the covariance is not finite");
      require_semidefinite(r, entry + " '" + path + "'");
      c.covariance = 0.5 * (covariance + covariance.transpose());
    }
  } // namespace

  UncertainConstants uncertain_constants(const Parameters &p, const Scene &scene)
  {
    const UncertaintyEntries &e = p.subsection<UncertaintyEntries>();
    UncertainConstants        c;
    c.mode    = e.mode;
    c.samples = e.samples;
    c.seed    = e.seed;
    if (!c.active())
      return c;
    const bool from_file = !trim_blanks(e.covariance_file).empty();
    const bool explicit_ = !trim_blanks(e.standard_deviations_text).empty();
    if (from_file == explicit_)
      throw InputError(section + "Mode = " + to_string(e.mode) + " needs " +
                       (from_file ? "one of" : "either") +
                       " Uncertainty/Covariance file and Uncertainty/Standard deviations" +
                       (from_file ? ", not both" : ""));
    if (from_file && !trim_blanks(e.correlations_text).empty())
      throw InputError(section + "Correlations: the correlations come from Uncertainty/"
                                 "Covariance file; give them with Standard deviations only");
    const std::vector<Candidate> list = candidates(*scene.law());
    if (from_file)
      file_constants(trim_blanks(e.covariance_file), list, c);
    else
      explicit_constants(e, scene, list, c);
    return c;
  }

  void require_uncertainty_support(const Parameters &p, const std::string &command)
  {
    const UncertaintyMode mode = p.subsection<UncertaintyEntries>().mode;
    if (mode == UncertaintyMode::none || command == "run")
      return;
    throw InputError(section + "Mode = " + to_string(mode) + ": cdea " + command +
                     " does not carry uncertainty into its answers yet (cdea run does); set "
                     "Uncertainty/Mode = none");
  }

  Eigen::MatrixXd sample_constants(const UncertainConstants &c, const Scene &scene,
                                   const unsigned int n, const unsigned int seed)
  {
    const Eigen::Index P = Eigen::Index(c.parameters.size());
    // A Cholesky factor L L^T = C; a semidefinite C (a correlation of +-1,
    // a zero standard deviation) by its eigenvectors, L = V sqrt(Lambda).
    Eigen::MatrixXd                     L;
    const Eigen::LLT<Eigen::MatrixXd> llt(c.covariance);
    if (llt.info() == Eigen::Success)
      L = llt.matrixL();
    else
      {
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(c.covariance);
        L = eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.).cwiseSqrt().asDiagonal();
      }
    Eigen::VectorXd mean(P);
    for (Eigen::Index j = 0; j < P; ++j)
      mean[j] = parameter_value(scene, c.parameters[std::size_t(j)]);
    std::mt19937_64                  random(seed);
    std::normal_distribution<double> normal;
    Eigen::MatrixXd                  values(n, P);
    Eigen::VectorXd                  z(P);
    for (unsigned int i = 0; i < n; ++i)
      {
        for (Eigen::Index j = 0; j < P; ++j)
          z[j] = normal(random);
        values.row(i) = (mean + L * z).transpose();
      }
    return values;
  }

  Scene with_constants(const Scene &scene, const UncertainConstants &c,
                       const Eigen::VectorXd &values)
  {
    Scene s = scene;
    for (std::size_t j = 0; j < c.parameters.size(); ++j)
      s = with_parameter(s, c.parameters[j], values[Eigen::Index(j)]);
    return s;
  }

  SampleStatistics sample_statistics(std::vector<double> values)
  {
    SampleStatistics s;
    s.n = values.size();
    if (values.empty())
      {
        s.mean = s.sd = NAN;
        s.percentiles.assign(3, NAN);
        return s;
      }
    std::sort(values.begin(), values.end());
    double sum = 0., squares = 0.;
    for (const double v : values)
      sum += v;
    s.mean = sum / double(s.n);
    for (const double v : values)
      squares += (v - s.mean) * (v - s.mean);
    s.sd = s.n > 1 ? std::sqrt(squares / double(s.n - 1)) : 0.;
    for (const double q : {5., 50., 95.})
      {
        // Between the order statistics: position q/100 (n - 1) from the first.
        const double      at = q / 100. * double(s.n - 1);
        const std::size_t k  = std::min(std::size_t(at), s.n - 1);
        const double      f  = at - double(k);
        s.percentiles.push_back(k + 1 < s.n ? (1. - f) * values[k] + f * values[k + 1] :
                                              values[k]);
      }
    return s;
  }
} // namespace cdea
