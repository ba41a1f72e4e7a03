// VTK XML writer for ParaView (the file formats of "VTK File Formats",
// VTK User's Guide): UnstructuredGrid pieces with their data appended as raw
// little- or big-endian bytes, each block preceded by its byte count (UInt64),
// and a Collection (PVD) listing one file per time.
#include <cdea/model/output_fields.h>
#include <cdea/output/paraview_writer.h>
#include <cdea/base/units.h>
#include <cdea/output/safe_files.h>

#include <sys/stat.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace cdea
{
  namespace
  {
    namespace fs = std::filesystem;

    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    bool little_endian()
    {
      const std::uint16_t one = 1;
      unsigned char       first;
      std::memcpy(&first, &one, 1);
      return first == 1;
    }

    const char *byte_order()
    {
      return little_endian() ? "LittleEndian" : "BigEndian";
    }

    /// The raw bytes after <AppendedData encoding="raw">_ and the XML that
    /// refers to them by offset.
    class AppendedData
    {
    public:
      template <typename T>
      void add(const std::string &name, const char *type, const std::vector<T> &values,
               const unsigned int components = 1)
      {
        xml << "        <DataArray type=\"" << type << "\"";
        if (!name.empty())
          xml << " Name=\"" << name << "\"";
        if (components > 1)
          xml << " NumberOfComponents=\"" << components << "\"";
        xml << " format=\"appended\" offset=\"" << bytes.size() << "\"/>\n";
        const std::uint64_t size = values.size() * sizeof(T);
        bytes.append(reinterpret_cast<const char *>(&size), sizeof(size));
        bytes.append(reinterpret_cast<const char *>(values.data()), size);
      }

      /// The XML written since the last call.
      std::string take_xml()
      {
        std::string s = xml.str();
        xml.str("");
        return s;
      }

      std::string bytes;

    private:
      std::ostringstream xml;
    };

    /// Points, cells and point data of one piece.
    struct Piece
    {
      std::vector<double>                            points; ///< x, y, z
      std::vector<std::int64_t>                      connectivity, offsets;
      std::vector<std::uint8_t>                      types;
      std::vector<std::pair<std::string, std::vector<double>>> reals;
      std::vector<std::int32_t>                      ring, wrinkled;

      void add_cell(const std::uint8_t type, std::initializer_list<std::int64_t> vertices)
      {
        connectivity.insert(connectivity.end(), vertices);
        offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
        types.push_back(type);
      }

      std::size_t n_points() const { return points.size() / 3; }
    };

    constexpr std::uint8_t vtk_triangle = 5, vtk_quad = 9;

    /// Names and values of the real point data of the film, in file units:
    /// the rows of the table of output fields marked for ParaView.
    std::vector<std::pair<std::string, std::vector<double>>> film_data(const StepFields &f)
    {
      std::vector<std::pair<std::string, std::vector<double>>> d;
      for (const StepField &row : step_fields())
        if (row.in_paraview && row.field.storage == Storage::real)
          d.emplace_back(row.field.name, in_unit(step_field_values(row, f), row.field.unit));
      return d;
    }

    /// The film: the meridian revolved about the axis in @p n segments.
    Piece film(const StepSummary &s, const StepFields &f, const unsigned int n)
    {
      Piece             p;
      const std::size_t m = f.R.size();
      const auto        data = film_data(f);
      p.reals.resize(data.size());
      for (std::size_t a = 0; a < data.size(); ++a)
        p.reals[a].first = data[a].first;
      for (std::size_t i = 0; i < m; ++i)
        {
          // As the summary's wrinkled column: not in the pre-stretch stage,
          // which starts from the stress-free film. Plain law: where s2 < 0.
          // Relaxed law (it reports a zone): s2 = 0 where wrinkled, also at
          // samples just outside the zone's quadrature points.
          const bool relaxed_zone = !std::isnan(s.wrinkled_zone_inner);
          const bool wrinkled =
            s.stage != Stage::prestretch &&
            (f.s2[i] < 0. ||
             (relaxed_zone && (f.s2[i] == 0. || (f.R[i] >= s.wrinkled_zone_inner &&
                                                 f.R[i] <= s.wrinkled_zone_outer))));
          for (unsigned int j = 0; j < n; ++j)
            {
              const double phi = 2. * M_PI * j / n;
              const double r = units::mm.from_si(f.r[i]);
              p.points.insert(p.points.end(),
                              {r * std::cos(phi), r * std::sin(phi), units::mm.from_si(f.z[i])});
              for (std::size_t a = 0; a < data.size(); ++a)
                p.reals[a].second.push_back(data[a].second[i]);
              p.ring.push_back(f.ring[i]);
              p.wrinkled.push_back(wrinkled);
            }
        }
      for (std::size_t i = 0; i + 1 < m; ++i)
        {
          if (!(f.R[i + 1] > f.R[i]))
            continue; // the two samples of a ring edge: no cell between them
          for (unsigned int j = 0; j < n; ++j)
            {
              const std::int64_t a = i * n + j, b = i * n + (j + 1) % n;
              p.add_cell(vtk_quad, {a, a + n, b + n, b});
            }
        }
      return p;
    }

    /// The rigid disk: a fan of triangles at z(A) out to r(A), with the
    /// film's point data (NaN where the disk has none, ring -1).
    Piece disk(const StepFields &f, const unsigned int n, const Piece &film_piece)
    {
      Piece        p;
      const double a = units::mm.from_si(f.r.front()), z = units::mm.from_si(f.z.front());
      p.points.insert(p.points.end(), {0., 0., z});
      for (unsigned int j = 0; j < n; ++j)
        {
          const double phi = 2. * M_PI * j / n;
          p.points.insert(p.points.end(), {a * std::cos(phi), a * std::sin(phi), z});
        }
      for (unsigned int j = 0; j < n; ++j)
        p.add_cell(vtk_triangle, {0, 1 + j, 1 + (j + 1) % n});
      for (const auto &[name, values] : film_piece.reals)
        {
          std::vector<double> v(n + 1, nan);
          if (name == "r")
            for (unsigned int j = 0; j <= n; ++j)
              v[j] = j == 0 ? 0. : a;
          else if (name == "z")
            v.assign(n + 1, z);
          p.reals.emplace_back(name, std::move(v));
        }
      p.ring.assign(n + 1, -1);
      p.wrinkled.assign(n + 1, 0);
      return p;
    }

    std::string number(const double x)
    {
      std::ostringstream o;
      o << std::setprecision(17) << x;
      return o.str();
    }

    void write_vtu(const std::string &path, const StepSummary &s, const double time,
                   const std::vector<Piece> &pieces)
    {
      AppendedData       data;
      std::ostringstream xml;
      xml << "<?xml version=\"1.0\"?>\n"
          << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"" << byte_order()
          << "\" header_type=\"UInt64\">\n  <UnstructuredGrid>\n    <FieldData>\n";
      const auto field = [&](const char *name, const char *type,
                             const std::vector<double> &values) {
        xml << "      <DataArray type=\"" << type << "\" Name=\"" << name
            << "\" NumberOfTuples=\"1\" NumberOfComponents=\"" << values.size()
            << "\" format=\"ascii\">";
        for (const double v : values)
          xml << ' ' << number(v);
        xml << " </DataArray>\n";
      };
      field("TimeValue", "Float64", {time});
      for (const Quantity *row : step_attributes())
        field(row->name, row->storage == Storage::integer ? "Int32" : "Float64",
              in_unit(row->summary_values(s), row->unit));
      xml << "    </FieldData>\n";
      for (const Piece &p : pieces)
        {
          xml << "    <Piece NumberOfPoints=\"" << p.n_points() << "\" NumberOfCells=\""
              << p.types.size() << "\">\n      <PointData Scalars=\"s2\">\n";
          for (const auto &[name, values] : p.reals)
            data.add(name, "Float64", values);
          data.add("ring", "Int32", p.ring);
          data.add("wrinkled", "Int32", p.wrinkled);
          xml << data.take_xml() << "      </PointData>\n      <Points>\n";
          data.add("", "Float64", p.points, 3);
          xml << data.take_xml() << "      </Points>\n      <Cells>\n";
          data.add("connectivity", "Int64", p.connectivity);
          data.add("offsets", "Int64", p.offsets);
          data.add("types", "UInt8", p.types);
          xml << data.take_xml() << "      </Cells>\n    </Piece>\n";
        }
      xml << "  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n   _";
      const std::string head = xml.str(), tail = "\n  </AppendedData>\n</VTKFile>\n";
      std::vector<char> file(head.begin(), head.end());
      file.insert(file.end(), data.bytes.begin(), data.bytes.end());
      file.insert(file.end(), tail.begin(), tail.end());
      // Written whole, then renamed (replace_file): a file cut short (full
      // disk) never takes the name of a step's file. Not synced: a step's
      // file is written again if the run is repeated.
      const WriteOutcome out = replace_file(path, file, false);
      if (!out.ok)
        throw std::runtime_error("cannot write the ParaView file '" + path + "': " + out.message);
    }
  } // namespace

  double ParaViewWriter::step_file_bytes(const std::size_t samples, const unsigned int segments)
  {
    // Per point of the film: x, y, z and the real point data (Float64),
    // ring and wrinkled (Int32); per quadrilateral: four Int64 vertices, an
    // Int64 offset and a UInt8 type. The disk adds segments + 1 points.
    double reals = 0.;
    for (const StepField &row : step_fields())
      reals += row.in_paraview && row.field.storage == Storage::real;
    const double points = double(samples) * segments + segments + 1.;
    return points * (8. * (3. + reals) + 8.) + double(samples) * segments * 41. + 4096.;
  }

  ParaViewWriter::ParaViewWriter(const std::string &stem_, const unsigned int segments)
    : stem(stem_)
    , name(fs::path(stem_).filename().string())
    , segments(segments)
  {
    if (segments < 3)
      throw std::invalid_argument("ParaViewWriter: at least 3 segments are needed");
    // A partial output of a killed run is ours to replace, a link or another
    // file of that name is not; the folder is made new (mkdir fails on
    // anything there), so no link can send the files elsewhere.
    for (const std::string &file : {stem + ".pvd", stem + ".partial.pvd"})
      for (const std::string &name : {file, file + ".tmp"})
        if (const std::string why = not_replaceable(name); !why.empty())
          throw std::runtime_error("cannot write the ParaView file '" + name + "': " + why);
    const std::string partial = folder(true);
    struct stat       st      = {};
    std::error_code   error;
    for (const std::string &taken : {folder(false), stem + "_vtu.older"})
      if (::lstat(taken.c_str(), &st) == 0 && !S_ISDIR(st.st_mode))
        throw std::runtime_error("cannot write the ParaView folder '" + folder(false) + "': '" +
                                 taken + "' is " + (S_ISLNK(st.st_mode) ? "a symbolic link" :
                                                                          "not a folder") +
                                 " (remove it)");
    if (::lstat(partial.c_str(), &st) == 0)
      {
        if (!S_ISDIR(st.st_mode))
          throw std::runtime_error("cannot create the ParaView folder '" + partial +
                                   "': something that is not a folder is in the way "
                                   "(remove it)");
        fs::remove_all(partial, error);
      }
    if (::mkdir(partial.c_str(), 0755) != 0 || ::lstat(partial.c_str(), &st) != 0)
      throw std::runtime_error("cannot create the ParaView folder '" + partial +
                               "': " + std::strerror(errno));
    folder_device = st.st_dev;
    folder_inode  = st.st_ino;
  }

  bool ParaViewWriter::older_output_exists() const
  {
    return file_exists(stem + ".pvd") || file_exists(folder(false));
  }

  std::string ParaViewWriter::folder(const bool partial) const
  {
    return stem + (partial ? "_vtu.partial" : "_vtu");
  }

  double ParaViewWriter::next_time(const double tau, const double previous_tau,
                                   const double previous_time, bool &turned)
  {
    if (std::isnan(previous_time))
      return tau;
    if (!turned && tau > previous_tau)
      return tau;
    turned = true;
    // Past a turn of t: on by the change of t (and by a little at a
    // standstill, so that no two times are equal).
    return previous_time + std::max(std::abs(tau - previous_tau), 1e-9);
  }

  void ParaViewWriter::write_step(const StepSummary &summary, const StepFields &fields)
  {
    if (fields.R.empty())
      throw std::invalid_argument("ParaViewWriter: a step without samples");
    const double tau  = static_cast<int>(summary.stage) - 2 + summary.load_factor;
    if (const double bytes = step_file_bytes(fields.R.size(), segments); bytes > max_step_file_bytes)
      throw std::runtime_error(
        "a ParaView file of " + std::to_string(fields.R.size()) + " samples x " +
        std::to_string(segments) + " segments would take " + std::to_string(long(units::MB.from_si(bytes))) +
        " MB, more than the " + std::to_string(long(units::MB.from_si(max_step_file_bytes))) +
        " MB allowed per step: lower Output/ParaView segments");
    if (struct stat st = {}; ::lstat(folder(true).c_str(), &st) != 0 || !S_ISDIR(st.st_mode) ||
                             st.st_dev != folder_device || st.st_ino != folder_inode)
      throw std::runtime_error("the ParaView folder '" + folder(true) +
                               "' was removed or replaced during the run");
    const double time = next_time(tau, last_tau, times.empty() ? nan : times.back(), turned);
    last_tau          = tau;
    std::ostringstream file;
    file << name << '_' << std::setw(6) << std::setfill('0') << times.size() << ".vtu";
    const Piece membrane = film(summary, fields, segments);
    write_vtu(folder(true) + "/" + file.str(), summary, time,
              {membrane, disk(fields, segments, membrane)});
    times.push_back(time);
    write_collection(stem + ".partial.pvd", fs::path(folder(true)).filename().string());
  }

  void ParaViewWriter::write_collection(const std::string &path,
                                        const std::string &vtu_folder) const
  {
    std::ostringstream out;
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\""
        << byte_order() << "\">\n  <Collection>\n";
    for (std::size_t k = 0; k < times.size(); ++k)
      out << "    <DataSet timestep=\"" << number(times[k]) << "\" group=\"\" part=\"0\" file=\""
          << vtu_folder << '/' << name << '_' << std::setw(6) << std::setfill('0') << k
          << ".vtu\"/>\n"
          << std::setfill(' ');
    out << "  </Collection>\n</VTKFile>\n";
    const std::string  text    = out.str();
    const WriteOutcome written = replace_file(path, {text.begin(), text.end()}, false);
    if (!written.ok)
      throw std::runtime_error("cannot write the ParaView collection '" + path +
                               "': " + written.message);
  }

  void ParaViewWriter::finish()
  {
    // The older output is set aside, not removed, until the new one is in
    // place; if the new one cannot be moved in, the older one goes back.
    const std::string older = stem + "_vtu.older";
    std::error_code   error;
    if (!fs::is_directory(folder(true), error))
      throw std::runtime_error("cannot move the ParaView files to '" + folder(false) +
                               "': the folder '" + folder(true) + "' is gone");
    // Only a folder of ours is set aside and replaced: a link or a file
    // named <stem>_vtu or <stem>_vtu.older is not touched.
    for (const std::string &taken : {folder(false), older})
      if (struct stat st = {}; ::lstat(taken.c_str(), &st) == 0 && !S_ISDIR(st.st_mode))
        throw std::runtime_error("cannot move the ParaView files to '" + folder(false) + "': '" +
                                 taken + "' is not a folder (remove it; the files stay in '" +
                                 folder(true) + "')");
    fs::remove_all(older, error);
    const bool had_older = fs::exists(folder(false), error);
    if (had_older)
      fs::rename(folder(false), older, error);
    if (!error)
      fs::rename(folder(true), folder(false), error);
    if (error)
      {
        const std::string reason = error.message();
        if (had_older && !fs::exists(folder(false), error))
          fs::rename(older, folder(false), error);
        throw std::runtime_error("cannot move the ParaView files to '" + folder(false) +
                                 "': " + reason + " (they stay in '" + folder(true) + "')");
      }
    write_collection(stem + ".pvd", fs::path(folder(false)).filename().string());
    fs::remove(stem + ".partial.pvd", error);
    fs::remove_all(older, error);
  }
} // namespace cdea
