// `cdea sweep FILE.prm`: input of the subsection Sweep, the distribution of
// the map's rows over the MPI ranks, progress display and the command itself.
// The continuation of one row is in sweep_row.cc, the file in sweep_file.cc.

#include <cdea/app/commands.h>
#include <cdea/app/parameters.h>
#include <cdea/app/sweep.h>

#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <system_error>

namespace cdea
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    std::string format(const double x)
    {
      std::ostringstream o;
      o << x;
      return o.str();
    }

    std::string trim(const std::string &s)
    {
      const auto first = s.find_first_not_of(" \t");
      if (first == std::string::npos)
        return "";
      const auto last = s.find_last_not_of(" \t");
      return s.substr(first, last - first + 1);
    }

    /// Round to 12 decimals: generated values equal the typed ones.
    double round12(const double x) { return std::round(x * 1e12) / 1e12; }

    constexpr std::size_t max_values = 100000;
  } // namespace

  std::vector<double> expand_value_list(const std::string &text, const std::string &name)
  {
    // Items: numbers, or the marker "..." (represented by NaN in `items`).
    std::vector<double>      items;
    std::vector<std::string> tokens;
    std::stringstream        stream(text);
    std::string              item;
    while (std::getline(stream, item, ','))
      {
        const std::string token = trim(item);
        if (token.empty())
          throw InputError(name + ": empty entry in '" + text +
                           "' (expected numbers separated by ',', and '...')");
        if (token == "...")
          {
            items.push_back(nan);
            tokens.push_back(token);
            continue;
          }
        items.push_back(parse_number(token, name, text));
        tokens.push_back(token);
      }
    if (!text.empty() && text.back() == ',')
      throw InputError(name + ": empty entry at the end of '" + text + "'");
    if (items.empty())
      throw InputError(name + ": no value given (expected numbers separated by ',')");

    std::vector<double> values;
    for (std::size_t i = 0; i < items.size(); ++i)
      {
        if (!std::isnan(items[i]))
          {
            values.push_back(items[i]);
            continue;
          }
        if (i < 2 || std::isnan(items[i - 1]) || std::isnan(items[i - 2]) ||
            i + 1 >= items.size() || std::isnan(items[i + 1]))
          throw InputError(name + ": '...' needs two numbers before it and one after it (in '" +
                           text + "')");
        const double a = items[i - 2], b = items[i - 1], c = items[i + 1];
        const double d = b - a;
        if (d == 0.)
          throw InputError(name + ": the two values before '...' are equal (" + format(a) +
                           "), so they define no sequence");
        const double steps = (c - b) / d;
        const double k_end = std::round(steps);
        if (k_end < 1.)
          throw InputError(name + ": " + tokens[i + 1] + " after '...' does not continue " +
                           tokens[i - 2] + ", " + tokens[i - 1] + " (step " + format(d) + ")");
        if (std::abs(steps - k_end) > 1e-6)
          throw InputError(name + ": " + tokens[i + 1] + " after '...' is not on the sequence " +
                           tokens[i - 2] + ", " + tokens[i - 1] + ", ... (step " + format(d) +
                           ")");
        if (k_end > double(max_values))
          throw InputError(name + ": '" + text + "' has more than " +
                           std::to_string(max_values) + " values");
        for (long k = 1; k < long(k_end); ++k)
          values.push_back(round12(b + k * d));
      }
    if (values.size() > max_values)
      throw InputError(name + ": '" + text + "' has more than " + std::to_string(max_values) +
                       " values");
    return values;
  }

  SweepSettings sweep_settings(const Parameters &p, const Scene &scene)
  {
    // The lines are defined by the sign of the plain law's hoop stress, and
    // the map is of the actuator under its dead load alone.
    if (p.wrinkling.model != WrinklingModel::check)
      throw InputError("Wrinkling/Model = " + to_string(p.wrinkling.model) +
                       " is not supported by cdea sweep: the red and blue lines are defined "
                       "by the hoop stress of the plain membrane law (use check)");
    if (p.reservoir.water_load)
      throw InputError("Reservoir/Water load = true is not supported by cdea sweep: the maps "
                       "are of the actuator under its dead load alone (use false)");
    if (p.time.enabled)
      throw InputError("Time/Enabled = true is not supported by cdea sweep: the maps are "
                       "quasi-static (use false)");
    SweepSettings s;
    const double  b_over_a = scene.frame_radius / scene.disk_radius;

    const std::string edges_name = "Sweep/Ring edge values (r/a)";
    s.ring_edge_values           = expand_value_list(p.sweep.ring_edge_values_text, edges_name);
    for (const double v : s.ring_edge_values)
      if (!(v > 1. && v < b_over_a))
        throw InputError(edges_name + ": " + format(v) + " is not inside (1, " +
                         format(b_over_a) + "): r_v/a must lie strictly between the disk edge "
                         "and the frame (b/a)");
    for (std::size_t i = 1; i < s.ring_edge_values.size(); ++i)
      if (!(s.ring_edge_values[i] > s.ring_edge_values[i - 1]))
        throw InputError(edges_name + ": values must increase strictly, but " +
                         format(s.ring_edge_values[i]) + " follows " +
                         format(s.ring_edge_values[i - 1]));

    const std::string inner_name = "Sweep/Inner voltage (kV)";
    if (!(p.sweep.inner_voltage_kV > 0.) || !std::isfinite(p.sweep.inner_voltage_kV))
      throw InputError(inner_name + " must be positive (the stroke increase is relative to "
                       "the stroke with both rings at it), got " +
                       format(p.sweep.inner_voltage_kV));
    s.inner_voltage = std::round(p.sweep.inner_voltage_kV * 1e12) / 1e9;

    const std::string range_name = "Sweep/Outer voltage range (kV)";
    const auto        range = parse_number_list(p.sweep.outer_voltage_range_text, range_name);
    if (range.size() != 3)
      throw InputError(range_name + ": expected three numbers 'from, to, step', got '" +
                       p.sweep.outer_voltage_range_text + "'");
    const double from = range[0], to = range[1], step = range[2];
    if (from < 0.)
      throw InputError(range_name + ": voltages must not be negative, got from = " +
                       format(from));
    if (!(step > 0.))
      throw InputError(range_name + ": the step must be positive, got " + format(step));
    if (to < from)
      throw InputError(range_name + ": the range is empty: 'to' (" + format(to) +
                       ") is below 'from' (" + format(from) + ")");
    const double count = std::floor((to - from) / step + 1e-9) + 1.;
    if (count > double(max_values))
      throw InputError(range_name + ": " + format(count) + " voltages are too many (at most " +
                       std::to_string(max_values) + ")");
    s.outer_from = std::round(from * 1e12) / 1e9;
    s.outer_to   = std::round(to * 1e12) / 1e9;
    s.outer_step = std::round(step * 1e12) / 1e9;
    for (long k = 0; k < long(count); ++k)
      s.outer_voltages.push_back(std::round((from + k * step) * 1e12) / 1e9);
    // Land exactly on 'to' when it is on the grid.
    if (std::abs(from + (count - 1.) * step - to) <= 1e-9 * step)
      s.outer_voltages.back() = s.outer_to;
    return s;
  }

  SteppingSettings sweep_stepping_settings(const Parameters &p)
  {
    SteppingSettings s = stepping_settings(p);
    s.arc_length       = false;
    s.stability_check  = false;
    s.breakdown_field  = 0.;
    return s;
  }

  std::vector<std::size_t> rows_of_rank(const std::size_t n_rows, const unsigned int rank,
                                        const unsigned int size)
  {
    std::vector<std::size_t> rows;
    for (std::size_t i = rank; i < n_rows; i += std::max(1u, size))
      rows.push_back(i);
    return rows;
  }

  namespace
  {
    // ---------------------------------------------------------------------
    // Rows as bytes, for the gather (memcpy: the doubles arrive bit for bit).

    class Packer
    {
    public:
      std::vector<char> bytes;
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
        bytes.insert(bytes.end(), c, c + n);
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

    struct Mpi
    {
      bool         active = false;
      unsigned int rank = 0, size = 1;
      Mpi()
      {
        int initialized = 0, finalized = 0;
        MPI_Initialized(&initialized);
        MPI_Finalized(&finalized);
        active = initialized && !finalized;
        if (active)
          {
            int r = 0, s = 1;
            MPI_Comm_rank(MPI_COMM_WORLD, &r);
            MPI_Comm_size(MPI_COMM_WORLD, &s);
            rank = r;
            size = s;
          }
      }
    };

    constexpr int progress_tag = 7401;
  } // namespace

  SweepMap compute_sweep_map(const Parameters &p, const Scene &base,
                             const SweepSettings &settings,
                             const std::function<void(std::size_t)> &on_points)
  {
    const Mpi              mpi;
    const FeDiscretization disc     = fe_discretization(p);
    const NewtonSettings   newton   = newton_settings(p);
    const SteppingSettings stepping = sweep_stepping_settings(p);
    const std::size_t      n        = settings.ring_edge_values.size();
    const std::size_t      m        = settings.outer_voltages.size();

    SweepMap map;
    map.settings = settings;
    // The same on every rank (same input, same arithmetic).
    map.zero_voltage_displacement = zero_voltage_displacement(base, disc, newton, stepping);

    const std::vector<std::size_t> mine = rows_of_rank(n, mpi.rank, mpi.size);
    const bool distributed = mpi.active && mpi.size > 1;

    // Progress: rank 0 reports its own points and polls for the counts the
    // other ranks send (at most every 0.2 s and at the end of each row).
    std::deque<std::uint64_t> sent; // stable buffers of pending sends
    std::vector<MPI_Request>  requests;
    std::uint64_t             pending   = 0;
    auto                      last_send = std::chrono::steady_clock::now();
    std::uint64_t             received  = 0;
    const std::uint64_t       expected  = std::uint64_t(n - mine.size()) * m;
    auto poll = [&] {
      if (!distributed || mpi.rank != 0)
        return;
      int flag = 1;
      while (received < expected)
        {
          MPI_Status status;
          MPI_Iprobe(MPI_ANY_SOURCE, progress_tag, MPI_COMM_WORLD, &flag, &status);
          if (!flag)
            break;
          std::uint64_t count = 0;
          MPI_Recv(&count, 1, MPI_UINT64_T, status.MPI_SOURCE, progress_tag, MPI_COMM_WORLD,
                   MPI_STATUS_IGNORE);
          received += count;
          if (on_points)
            on_points(count);
        }
    };
    auto send = [&] {
      if (pending == 0)
        return;
      sent.push_back(pending);
      requests.emplace_back();
      MPI_Isend(&sent.back(), 1, MPI_UINT64_T, 0, progress_tag, MPI_COMM_WORLD,
                &requests.back());
      pending   = 0;
      last_send = std::chrono::steady_clock::now();
    };
    auto points_done = [&](const std::size_t count) {
      if (!distributed || mpi.rank == 0)
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
            row.message = std::string("error: ") + e.what();
            if (reported < m)
              points_done(m - reported);
          }
        if (distributed && mpi.rank != 0)
          send();
        if (distributed)
          pack(local, i, row);
        else
          map.rows.push_back(std::move(row));
      }
    if (!distributed)
      return map;

    if (mpi.rank == 0)
      while (received < expected)
        {
          std::uint64_t count = 0;
          MPI_Recv(&count, 1, MPI_UINT64_T, MPI_ANY_SOURCE, progress_tag, MPI_COMM_WORLD,
                   MPI_STATUS_IGNORE);
          received += count;
          if (on_points)
            on_points(count);
        }
    else if (!requests.empty())
      MPI_Waitall(int(requests.size()), requests.data(), MPI_STATUSES_IGNORE);

    // Gather the packed rows on rank 0.
    const int        bytes = int(local.bytes.size());
    std::vector<int> counts(mpi.rank == 0 ? mpi.size : 0), offsets;
    MPI_Gather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::vector<char> all;
    if (mpi.rank == 0)
      {
        offsets.assign(mpi.size, 0);
        std::size_t total = 0;
        for (unsigned int r = 0; r < mpi.size; ++r)
          {
            offsets[r] = int(total);
            total += std::size_t(counts[r]);
          }
        all.resize(std::max<std::size_t>(total, 1));
      }
    MPI_Gatherv(local.bytes.data(), bytes, MPI_CHAR, all.data(), counts.data(), offsets.data(),
                MPI_CHAR, 0, MPI_COMM_WORLD);
    if (mpi.rank != 0)
      {
        // Only the own rows on the other ranks.
        Unpacker in(local.bytes.data(), local.bytes.data() + local.bytes.size());
        while (!in.done())
          map.rows.push_back(unpack(in).second);
        return map;
      }
    map.rows.assign(n, SweepRow());
    std::vector<bool> seen(n, false);
    std::size_t       total = 0;
    for (unsigned int r = 0; r < mpi.size; ++r)
      total += std::size_t(counts[r]);
    Unpacker in(all.data(), all.data() + total);
    while (!in.done())
      {
        auto [index, row] = unpack(in);
        if (index >= n || seen[index])
          throw std::runtime_error("cdea sweep: bad row index in the gather");
        seen[index]     = true;
        map.rows[index] = std::move(row);
      }
    if (std::find(seen.begin(), seen.end(), false) != seen.end())
      throw std::runtime_error("cdea sweep: a row is missing after the gather");
    return map;
  }

  namespace
  {
    std::string duration(const double seconds)
    {
      std::ostringstream o;
      if (!std::isfinite(seconds))
        o << "?";
      else if (seconds < 60.)
        o << std::fixed << std::setprecision(seconds < 10. ? 1 : 0) << seconds << " s";
      else if (seconds < 3600.)
        o << int(seconds / 60.) << " min " << std::setw(2) << std::setfill('0')
          << int(std::fmod(seconds, 60.)) << " s";
      else
        o << int(seconds / 3600.) << " h " << std::setw(2) << std::setfill('0')
          << int(std::fmod(seconds, 3600.) / 60.) << " min";
      return o.str();
    }

    /// Points done, total and time left: a live bar on a terminal, plain
    /// lines every CDEA_PROGRESS_SECONDS (default 5) otherwise.
    class Progress
    {
    public:
      Progress(const std::size_t total, const bool enabled)
        : total(total)
        , enabled(enabled)
        , terminal(isatty(fileno(stdout)) != 0)
        , start(std::chrono::steady_clock::now())
        , last(start)
      {
        if (const char *env = std::getenv("CDEA_PROGRESS_SECONDS"))
          {
            char        *end = nullptr;
            const double v   = std::strtod(env, &end);
            if (end != env && v >= 0.)
              interval = v;
          }
        if (const char *env = std::getenv("CDEA_PROGRESS"))
          {
            const std::string mode = env;
            if (mode == "lines")
              terminal = false;
            else if (mode == "bar")
              terminal = true;
            else if (mode == "off")
              this->enabled = false;
          }
      }

      void add(const std::size_t count)
      {
        done += count;
        if (!enabled)
          return;
        const auto   now     = std::chrono::steady_clock::now();
        const double since   = std::chrono::duration<double>(now - last).count();
        if (terminal ? since >= 0.1 : since >= interval)
          {
            show(now);
            last = now;
          }
      }

      void finish()
      {
        if (!enabled)
          return;
        show(std::chrono::steady_clock::now());
        if (terminal)
          std::cout << std::endl;
      }

    private:
      std::size_t total, done = 0, shown = 0;
      bool        enabled, terminal;
      double      interval = 5.;
      std::chrono::steady_clock::time_point start, last;

      void show(const std::chrono::steady_clock::time_point now)
      {
        const double elapsed = std::chrono::duration<double>(now - start).count();
        const double left =
          done == 0 ? nan : elapsed * double(total - std::min(done, total)) / double(done);
        const double      fraction = total ? double(done) / double(total) : 1.;
        std::ostringstream line;
        line << done << '/' << total << " points (" << int(100. * fraction) << " %), "
             << duration(elapsed) << " elapsed, " << duration(left) << " left";
        if (terminal)
          {
            const int   width = 30, filled = int(width * fraction);
            std::string bar   = "  [" + std::string(filled, '#') +
                              std::string(width - filled, '.') + "] " + line.str();
            // Blank what a longer previous bar left behind.
            const std::size_t length = bar.size();
            if (bar.size() < shown)
              bar += std::string(shown - bar.size(), ' ');
            shown = length;
            std::cout << '\r' << bar << std::flush;
          }
        else
          std::cout << "  progress: " << line.str() << std::endl;
      }
    };

    std::string fixed(const double x, const int digits)
    {
      if (std::isnan(x))
        return "-";
      std::ostringstream o;
      o << std::fixed << std::setprecision(digits) << x;
      return o.str();
    }

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
    const Mpi   mpi;
    const bool  root = mpi.rank == 0;
    Parameters  p;
    Scene       base;
    std::string text;
    SweepSettings settings;
    try
      {
        p        = read_parameters(prm_file, &text);
        base     = p.scene();
        settings = sweep_settings(p, base);
      }
    catch (const InputError &e)
      {
        if (root)
          std::cerr << "cdea: " << e.what() << '\n';
        return exit_input_error;
      }
    const std::string path = p.results_path("_map");

    // The output folder must be writable before hours of work start.
    int writable = 1;
    if (root)
      {
        std::error_code error;
        const auto      dir = std::filesystem::path(path).parent_path();
        if (!dir.empty())
          std::filesystem::create_directories(dir, error);
        if (error || access(dir.empty() ? "." : dir.c_str(), W_OK) != 0)
          {
            std::cerr << "cdea: cannot write '" << path << "': the directory '"
                      << dir.string() << "' cannot be created or is not writable"
                      << (error ? ": " + error.message() : std::string()) << '\n';
            writable = 0;
          }
      }
    if (mpi.active && mpi.size > 1)
      MPI_Bcast(&writable, 1, MPI_INT, 0, MPI_COMM_WORLD);
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
                << p.discretization.elements_per_ring << " elements per ring; " << mpi.size
                << (mpi.size == 1 ? " rank" : " ranks") << " (rows round-robin); writing "
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
        std::cerr << "cdea: sweep failed: " << e.what() << '\n';
        return exit_input_error;
      }
    progress.finish();
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!root)
      return exit_success;

    try
      {
        write_sweep_file(path, map, text);
      }
    catch (const std::exception &e)
      {
        std::cerr << "cdea: " << e.what() << '\n';
        std::error_code ignored;
        std::filesystem::remove(path, ignored); // no half-written map
        return exit_input_error;
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
        std::cout << std::setw(7) << r.rv_over_a << std::setw(11) << fixed(r.base_displacement * 1e3, 4)
                  << std::setw(12) << fixed(r.highest_voltage / 1e3, 3) << std::setw(10)
                  << fixed(r.red.outer_voltage / 1e3, 4) << std::setw(10)
                  << fixed(r.red.stroke_increase, 2) << std::setw(10)
                  << fixed(r.blue.outer_voltage / 1e3, 4) << std::setw(10)
                  << fixed(r.blue.stroke_increase, 2) << "  "
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
                    << fixed((map.rows[i].*line).stroke_increase, 2) << " % at r_v/a = "
                    << map.rows[i].rv_over_a << " (outer "
                    << fixed((map.rows[i].*line).outer_voltage / 1e3, 4) << " kV)\n";
      }
    std::cout << n * m << " map points, " << solves << " equilibrium solves, " << iterations
              << " Newton iterations, " << std::setprecision(3) << seconds << " s on "
              << mpi.size << (mpi.size == 1 ? " rank" : " ranks") << "\nwrote " << path << '\n';
    return exit_success;
  }
} // namespace cdea
