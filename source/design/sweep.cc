// `cdea sweep FILE.prm`: the map's rows over the MPI ranks, progress display
// and the command itself. The input is read in sweep_settings.cc, one row is
// continued in sweep_row.cc, the file is written in sweep_file.cc.

#include <cdea/analysis/commands.h>
#include <cdea/base/mpi_session.h>
#include <cdea/input/parameters.h>
#include <cdea/base/run_control.h>
#include <cdea/base/progress.h>
#include <cdea/design/sweep.h>
#include <cdea/base/format.h>
#include <cdea/output/safe_files.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace cdea
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  } // namespace


  namespace
  {
    // ---------------------------------------------------------------------
    // Rows as bytes, for the gather (memcpy: the doubles arrive bit for bit).

    class Packer
    {
    public:
      std::string bytes;
      void put(const double x) { append(&x, sizeof x); }
      void put(const std::uint64_t x) { append(&x, sizeof x); }
      void put(const std::string &s)
      {
        put(std::uint64_t(s.size()));
        append(s.data(), s.size());
      }
      void put(const std::vector<double> &v)
      {
        put(std::uint64_t(v.size()));
        append(v.data(), v.size() * sizeof(double));
      }
      void put(const SweepLine &l)
      {
        for (const double x : {l.outer_voltage, l.displacement, l.stroke_increase, l.s2_inner[0],
                               l.s2_inner[1], l.bracket_width})
          put(x);
        put(std::uint64_t(l.evaluations));
      }

    private:
      void append(const void *p, const std::size_t n)
      {
        const char *c = static_cast<const char *>(p);
        bytes.append(c, n);
      }
    };

    class Unpacker
    {
    public:
      Unpacker(const char *begin, const char *end)
        : p(begin)
        , end(end)
      {}
      bool done() const { return p == end; }
      double        get_double() { return get<double>(); }
      std::uint64_t get_uint() { return get<std::uint64_t>(); }
      std::string   get_string()
      {
        const std::size_t n = get_uint();
        need(n);
        std::string s(p, n);
        p += n;
        return s;
      }
      std::vector<double> get_vector()
      {
        const std::size_t   n = get_uint();
        std::vector<double> v(n);
        need(n * sizeof(double));
        std::memcpy(v.data(), p, n * sizeof(double));
        p += n * sizeof(double);
        return v;
      }
      SweepLine get_line()
      {
        SweepLine l;
        l.outer_voltage   = get_double();
        l.displacement    = get_double();
        l.stroke_increase = get_double();
        l.s2_inner[0]     = get_double();
        l.s2_inner[1]     = get_double();
        l.bracket_width   = get_double();
        l.evaluations     = get_uint();
        return l;
      }

    private:
      const char *p, *end;
      void        need(const std::size_t n) const
      {
        if (std::size_t(end - p) < n)
          throw std::runtime_error("cdea sweep: truncated row data in the gather");
      }
      template <typename T>
      T get()
      {
        need(sizeof(T));
        T x;
        std::memcpy(&x, p, sizeof(T));
        p += sizeof(T);
        return x;
      }
    };

    void pack(Packer &out, const std::size_t index, const SweepRow &r)
    {
      out.put(std::uint64_t(index));
      out.put(r.rv_over_a);
      out.put(std::uint64_t(r.base_reached));
      for (const double x : {r.base_displacement, r.base_s2_inner[0], r.base_s2_inner[1],
                             r.lowest_voltage, r.highest_voltage, r.seconds, r.base_seconds,
                             r.line_seconds})
        out.put(x);
      out.put(r.message);
      for (const auto *v :
           {&r.displacement, &r.stroke, &r.stroke_increase, &r.s2_inner_ring1, &r.s2_inner_ring2})
        out.put(*v);
      out.put(r.red);
      out.put(r.blue);
      for (const unsigned int c : {r.solves, r.newton_iterations, r.base_solves, r.base_iterations,
                                   r.line_solves, r.line_iterations, r.failed_solves,
                                   r.failed_iterations})
        out.put(std::uint64_t(c));
    }

    std::pair<std::size_t, SweepRow> unpack(Unpacker &in)
    {
      SweepRow          r;
      const std::size_t index = in.get_uint();
      r.rv_over_a             = in.get_double();
      r.base_reached          = in.get_uint() != 0;
      r.base_displacement     = in.get_double();
      r.base_s2_inner[0]      = in.get_double();
      r.base_s2_inner[1]      = in.get_double();
      r.lowest_voltage        = in.get_double();
      r.highest_voltage       = in.get_double();
      r.seconds               = in.get_double();
      r.base_seconds          = in.get_double();
      r.line_seconds          = in.get_double();
      r.message               = in.get_string();
      for (auto *v :
           {&r.displacement, &r.stroke, &r.stroke_increase, &r.s2_inner_ring1, &r.s2_inner_ring2})
        *v = in.get_vector();
      r.red               = in.get_line();
      r.blue              = in.get_line();
      for (unsigned int *c : {&r.solves, &r.newton_iterations, &r.base_solves,
                              &r.base_iterations, &r.line_solves, &r.line_iterations,
                              &r.failed_solves, &r.failed_iterations})
        *c = static_cast<unsigned int>(in.get_uint());
      return {index, std::move(r)};
    }

    constexpr int progress_tag = 7401;
  } // namespace

  SweepMap compute_sweep_map(const Parameters &p, const Scene &base,
                             const SweepSettings &settings,
                             const std::function<void(std::size_t)> &on_points)
  {
    const FeDiscretization disc     = fe_discretization(p);
    const NewtonSettings   newton   = newton_settings(p);
    const SteppingSettings stepping = sweep_stepping_settings(p);
    const std::size_t      n        = settings.ring_edge_values.size();
    const std::size_t      m        = settings.outer_voltages.size();

    SweepMap map;
    map.settings = settings;
    // The same on every rank (same input, same arithmetic).
    map.zero_voltage_displacement = zero_voltage_displacement(base, disc, newton, stepping);

    const unsigned int             rank = mpi::rank(), size = mpi::size();
    const std::vector<std::size_t> mine = rows_of_rank(n, rank, size);
    const bool                     distributed = size > 1;

    // Progress: rank 0 reports its own points and polls for the counts the
    // other ranks send (at most every 0.2 s and at the end of each row).
    mpi::CountChannel   channel(progress_tag);
    std::uint64_t       pending   = 0;
    auto                last_send = std::chrono::steady_clock::now();
    std::uint64_t       received  = 0;
    const std::uint64_t expected  = std::uint64_t(n - mine.size()) * m;
    auto poll = [&] {
      if (!distributed || rank != 0)
        return;
      std::uint64_t count = 0;
      while (received < expected && channel.try_receive(count))
        {
          received += count;
          if (on_points)
            on_points(count);
        }
    };
    auto send = [&] {
      if (pending == 0)
        return;
      channel.send(pending);
      pending   = 0;
      last_send = std::chrono::steady_clock::now();
    };
    auto points_done = [&](const std::size_t count) {
      if (!distributed || rank == 0)
        {
          if (on_points)
            on_points(count);
          poll();
          return;
        }
      pending += count;
      if (std::chrono::steady_clock::now() - last_send > std::chrono::milliseconds(200))
        send();
    };

    Packer local;
    for (const std::size_t i : mine)
      {
        const double rv       = settings.ring_edge_values[i];
        std::size_t  reported = 0;
        SweepRow     row;
        try
          {
            const Scene   scene = sweep_scene(base, rv, settings.inner_voltage);
            MembraneModel model(scene, disc, newton);
            row = compute_sweep_row(model, scene, settings, stepping,
                                    map.zero_voltage_displacement, [&](const std::size_t c) {
                                      reported += c;
                                      points_done(c);
                                    });
          }
        catch (const std::exception &e)
          {
            // Recorded, not fatal: the row stays NaN and the other ranks go on.
            row           = SweepRow();
            row.rv_over_a = rv;
            for (auto *v : {&row.displacement, &row.stroke, &row.stroke_increase,
                            &row.s2_inner_ring1, &row.s2_inner_ring2})
              v->assign(m, nan);
            row.message = "error: " + one_line_message(e);
            if (reported < m)
              points_done(m - reported);
          }
        if (distributed && rank != 0)
          send();
        if (distributed)
          pack(local, i, row);
        else
          map.rows.push_back(std::move(row));
      }
    if (!distributed)
      return map;

    if (rank == 0)
      while (received < expected)
        {
          const std::uint64_t count = channel.receive();
          received += count;
          if (on_points)
            on_points(count);
        }
    else
      channel.wait_for_sends();

    // Gather the packed rows on rank 0; the other ranks keep their own.
    const std::vector<std::string> packed = mpi::gather_bytes(local.bytes);
    if (rank != 0)
      {
        Unpacker in(local.bytes.data(), local.bytes.data() + local.bytes.size());
        while (!in.done())
          map.rows.push_back(unpack(in).second);
        return map;
      }
    map.rows.assign(n, SweepRow());
    std::vector<bool> seen(n, false);
    for (const std::string &bytes : packed)
      {
        Unpacker in(bytes.data(), bytes.data() + bytes.size());
        while (!in.done())
          {
            auto [index, row] = unpack(in);
            if (index >= n || seen[index])
              throw std::runtime_error("cdea sweep: bad row index in the gather");
            seen[index]     = true;
            map.rows[index] = std::move(row);
          }
      }
    if (std::find(seen.begin(), seen.end(), false) != seen.end())
      throw std::runtime_error("cdea sweep: a row is missing after the gather");
    return map;
  }

  namespace
  {
    /// The maximum of a line's stroke increase over the rows (index or n).
    std::size_t line_maximum(const SweepMap &map, SweepLine SweepRow::*line)
    {
      std::size_t best = map.rows.size();
      for (std::size_t i = 0; i < map.rows.size(); ++i)
        {
          const double x = (map.rows[i].*line).stroke_increase;
          if (!std::isnan(x) &&
              (best == map.rows.size() || x > (map.rows[best].*line).stroke_increase))
            best = i;
        }
      return best;
    }
  } // namespace

  int run_sweep(const std::string &prm_file)
  {
    const bool  root = mpi::rank() == 0;
    Parameters  p;
    Scene       base;
    std::string text;
    SweepSettings settings;
    try
      {
        p        = read_parameters(prm_file, &text);
        base     = p.scene();
        settings = sweep_settings(p, base);
        for (const std::string &warning : p.input_warnings)
          if (root)
            std::cerr << "cdea: warning: " << warning << '\n';
      }
    catch (const InputError &e)
      {
        if (root)
          std::cerr << "cdea: " << e.what() << '\n';
        return exit_input_error;
      }
    const std::string path = p.results_path("_map");

    // The output folder must be writable, and the map file ours alone,
    // before hours of work start. Directories made here go again if no map
    // is written.
    int                      writable = 1;
    OutputLock               lock;
    std::vector<std::string> created;
    std::string              why;
    if (root && !claim_output(path, lock, why, &created))
      {
        std::cerr << "cdea: cannot write '" << path << "': " << why << '\n';
        writable = 0;
      }
    mpi::broadcast(writable);
    if (!writable)
      return exit_input_error;

    const std::size_t n = settings.ring_edge_values.size(), m = settings.outer_voltages.size();
    if (root)
      std::cout << "cdea " << CDEA_VERSION << " sweep: " << n << " layouts r_v/a = "
                << settings.ring_edge_values.front() << " .. " << settings.ring_edge_values.back()
                << " x " << m << " outer voltages " << settings.outer_from / 1e3 << " .. "
                << settings.outer_voltages.back() / 1e3 << " kV (step "
                << settings.outer_step / 1e3 << " kV), inner ring at "
                << settings.inner_voltage / 1e3 << " kV\n"
                << "FE model: degree " << p.discretization.polynomial_degree << ", "
                << p.discretization.elements_per_ring << " elements per ring; " << mpi::size()
                << (mpi::size() == 1 ? " rank" : " ranks") << " (rows round-robin); writing "
                << path << std::endl;

    const auto start = std::chrono::steady_clock::now();
    Progress   progress(n * m, root);
    SweepMap   map;
    try
      {
        map = compute_sweep_map(p, base, settings,
                                [&](const std::size_t c) { progress.add(c); });
      }
    catch (const std::exception &e)
      {
        std::cerr << "cdea: sweep failed: " << one_line_message(e) << '\n';
        lock.release();
        remove_created_directories(created);
        return exit_input_error;
      }
    progress.finish();
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!root)
      return exit_success;

    const bool no_row_reached = !some_row_reached(map);
    try
      {
        write_sweep_file(path, map, text);
      }
    catch (const std::exception &e)
      {
        std::cerr << "cdea: " << e.what() << " (the map is lost; an older map stays)\n";
        return exit_not_complete;
      }

    // Table: one line per layout.
    std::cout << "\nzero-voltage displacement under the dead load: " << std::setprecision(7)
              << map.zero_voltage_displacement * 1e3 << " mm\n"
              << std::setw(7) << "r_v/a" << std::setw(11) << "base (mm)" << std::setw(12)
              << "reached kV" << std::setw(10) << "red kV" << std::setw(10) << "red %"
              << std::setw(10) << "blue kV" << std::setw(10) << "blue %" << "  stop\n";
    unsigned long solves = 0, iterations = 0;
    for (const SweepRow &r : map.rows)
      {
        solves += r.solves;
        iterations += r.newton_iterations;
        std::cout << std::setw(7) << r.rv_over_a << std::setw(11) << format_fixed_or_dash(r.base_displacement * 1e3, 4)
                  << std::setw(12) << format_fixed_or_dash(r.highest_voltage / 1e3, 3) << std::setw(10)
                  << format_fixed_or_dash(r.red.outer_voltage / 1e3, 4) << std::setw(10)
                  << format_fixed_or_dash(r.red.stroke_increase, 2) << std::setw(10)
                  << format_fixed_or_dash(r.blue.outer_voltage / 1e3, 4) << std::setw(10)
                  << format_fixed_or_dash(r.blue.stroke_increase, 2) << "  "
                  << (r.message.empty() ? "-" : r.message.substr(0, 60)) << '\n';
      }
    for (const auto &[name, line] :
         {std::pair<const char *, SweepLine SweepRow::*>{"red", &SweepRow::red},
          std::pair<const char *, SweepLine SweepRow::*>{"blue", &SweepRow::blue}})
      {
        const std::size_t i = line_maximum(map, line);
        if (i == map.rows.size())
          std::cout << "largest stroke increase on the " << name << " line: none in the range\n";
        else
          std::cout << "largest stroke increase on the " << name << " line: "
                    << format_fixed_or_dash((map.rows[i].*line).stroke_increase, 2) << " % at r_v/a = "
                    << map.rows[i].rv_over_a << " (outer "
                    << format_fixed_or_dash((map.rows[i].*line).outer_voltage / 1e3, 4) << " kV)\n";
      }
    std::cout << n * m << " map points, " << solves << " equilibrium solves, " << iterations
              << " Newton iterations, " << std::setprecision(3) << seconds << " s on "
              << mpi::size() << (mpi::size() == 1 ? " rank" : " ranks") << "\nwrote " << path << '\n';
    if (no_row_reached)
      {
        std::cerr << "cdea: no layout reached the inner voltage of "
                  << settings.inner_voltage / 1e3 << " kV (first row: "
                  << (map.rows.empty() ? std::string("none") : map.rows.front().message)
                  << "): the map is empty\n";
        return exit_not_complete;
      }
    return exit_success;
  }

  namespace
  {
    double seconds_since(const std::chrono::steady_clock::time_point start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  } // namespace

  SweepRecord sweep_in_memory(const ParameterInput &input)
  {
    SweepRecord         record;
    const Parameters    p        = read_parameters(input, &record.parameters);
    const Scene         base     = p.scene();
    const SweepSettings settings = sweep_settings(p, base);
    record.results_path          = p.results_path("_map");
    const auto start             = std::chrono::steady_clock::now();
    record.map                   = compute_sweep_map(p, base, settings);
    record.seconds               = seconds_since(start);
    return record;
  }
} // namespace cdea
