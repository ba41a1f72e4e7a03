// The map of `cdea sweep`: its rows dealt round-robin to the MPI ranks,
// their progress relayed to rank 0 and the rows gathered there; the map of one
// process in memory (the Python module). The input is read in
// sweep_settings.cc, one row is continued in sweep_row.cc, the file is
// written in sweep_file.cc; the command is commands/sweep.cc.

#include <cdea/base/byte_pack.h>
#include <cdea/base/mpi_session.h>
#include <cdea/base/run_control.h>
#include <cdea/design/sweep.h>
#include <cdea/input/parameter_input.h>
#include <cdea/input/parameters.h>
#include <cdea/input/solver_settings.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>

namespace cdea
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    // Rows as bytes for the gather (base/byte_pack.h).

    void put_line(BytePacker &out, const SweepLine &l)
    {
      for (const double x : {l.outer_voltage, l.displacement, l.stroke_increase, l.s2_inner[0],
                             l.s2_inner[1], l.bracket_width})
        out.put(x);
      out.put(std::uint64_t(l.evaluations));
    }

    SweepLine get_line(ByteUnpacker &in)
    {
      SweepLine l;
      l.outer_voltage   = in.get_double();
      l.displacement    = in.get_double();
      l.stroke_increase = in.get_double();
      l.s2_inner[0]     = in.get_double();
      l.s2_inner[1]     = in.get_double();
      l.bracket_width   = in.get_double();
      l.evaluations     = in.get_uint();
      return l;
    }

    void pack(BytePacker &out, const std::size_t index, const SweepRow &r)
    {
      out.put(std::uint64_t(index));
      out.put(r.rv_over_a);
      out.put(std::uint64_t(r.base_reached));
      out.put(std::uint64_t(r.skipped));
      for (const double x : {r.base_displacement, r.base_s2_inner[0], r.base_s2_inner[1],
                             r.lowest_voltage, r.highest_voltage, r.seconds, r.base_seconds,
                             r.line_seconds})
        out.put(x);
      out.put(r.message);
      for (const auto *v :
           {&r.displacement, &r.stroke, &r.stroke_increase, &r.s2_inner_ring1, &r.s2_inner_ring2})
        out.put(*v);
      put_line(out, r.red);
      put_line(out, r.blue);
      for (const unsigned int c : {r.solves, r.newton_iterations, r.base_solves, r.base_iterations,
                                   r.line_solves, r.line_iterations, r.failed_solves,
                                   r.failed_iterations})
        out.put(std::uint64_t(c));
    }

    std::pair<std::size_t, SweepRow> unpack(ByteUnpacker &in)
    {
      SweepRow          r;
      const std::size_t index = in.get_uint();
      r.rv_over_a             = in.get_double();
      r.base_reached          = in.get_uint() != 0;
      r.skipped               = in.get_uint() != 0;
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
      r.red               = get_line(in);
      r.blue              = get_line(in);
      for (unsigned int *c : {&r.solves, &r.newton_iterations, &r.base_solves,
                              &r.base_iterations, &r.line_solves, &r.line_iterations,
                              &r.failed_solves, &r.failed_iterations})
        *c = static_cast<unsigned int>(in.get_uint());
      return {index, std::move(r)};
    }

    constexpr int progress_tag = 7401;

    /// Grid points done, told to on_points on rank 0 as they come in: rank 0
    /// reports its own at once and polls for the counts of the other ranks,
    /// which send theirs at most every 0.2 s and at the end of each row.
    class ProgressRelay
    {
    public:
      ProgressRelay(const std::uint64_t                     expected_from_others,
                    const std::function<void(std::size_t)> &on_points)
        : distributed(mpi::size() > 1)
        , root(mpi::rank() == 0)
        , channel(progress_tag)
        , expected(expected_from_others)
        , on_points(on_points)
        , last_send(std::chrono::steady_clock::now())
      {}

      /// @p count more points of this rank are done.
      void add(const std::size_t count)
      {
        if (!distributed || root)
          {
            if (on_points)
              on_points(count);
            poll();
            return;
          }
        pending += count;
        if (std::chrono::steady_clock::now() - last_send > std::chrono::milliseconds(200))
          send();
      }

      /// At the end of a row: what this rank has not sent yet leaves now.
      void end_of_row()
      {
        if (distributed && !root)
          send();
      }

      /// At the end of this rank's rows: rank 0 takes every count still to
      /// come, the others wait until theirs have left.
      void finish()
      {
        if (!distributed)
          return;
        if (!root)
          {
            channel.wait_for_sends();
            return;
          }
        while (received < expected)
          {
            const std::uint64_t count = channel.receive();
            received += count;
            if (on_points)
              on_points(count);
          }
      }

    private:
      const bool                              distributed, root;
      mpi::CountChannel                       channel;
      const std::uint64_t                     expected;
      const std::function<void(std::size_t)> &on_points;
      std::uint64_t                           pending = 0, received = 0;
      std::chrono::steady_clock::time_point   last_send;

      void poll()
      {
        if (!distributed)
          return;
        std::uint64_t count = 0;
        while (received < expected && channel.try_receive(count))
          {
            received += count;
            if (on_points)
              on_points(count);
          }
      }

      void send()
      {
        if (pending == 0)
          return;
        channel.send(pending);
        pending   = 0;
        last_send = std::chrono::steady_clock::now();
      }
    };

    /// A row without results (NaN everywhere) that says why.
    SweepRow empty_row(const double rv, const std::size_t m, const std::string &message)
    {
      SweepRow row;
      row.rv_over_a = rv;
      for (auto *v : {&row.displacement, &row.stroke, &row.stroke_increase,
                      &row.s2_inner_ring1, &row.s2_inner_ring2})
        v->assign(m, nan);
      row.message = message;
      return row;
    }

    /// What every row of a map shares: its settings and the models' settings.
    struct RowContext
    {
      const Scene           &base;
      const SweepSettings   &settings;
      const FeDiscretization disc;
      const NewtonSettings   newton;
      const SteppingSettings stepping;
      double                 zero_voltage_displacement;
    };

    /// Row @p rv of the map, its points reported to @p progress. An error is
    /// recorded, not fatal: the row stays NaN and the other ranks go on.
    SweepRow map_row(const RowContext &c, const double rv, ProgressRelay &progress)
    {
      const std::size_t m = c.settings.outer_voltages.size();
      if (const int signal = StopOnSignals::requested())
        {
          SweepRow row = empty_row(rv, m, RunInterrupted(signal).what());
          row.skipped  = true;
          progress.add(m);
          return row;
        }
      std::size_t reported = 0;
      try
        {
          const Scene   scene = sweep_scene(c.base, rv, c.settings.inner_voltage);
          MembraneModel model(scene, c.disc, c.newton);
          return compute_sweep_row(model, scene, c.settings, c.stepping,
                                   c.zero_voltage_displacement, [&](const std::size_t count) {
                                     reported += count;
                                     progress.add(count);
                                   });
        }
      catch (const std::exception &e)
        {
          if (reported < m)
            progress.add(m - reported);
          return empty_row(rv, m, "error: " + one_line_message(e));
        }
    }

    /// Every rank's packed rows gathered on rank 0 into @p rows (n of them,
    /// in map order); the other ranks keep their own.
    void gather_rows(const BytePacker &local, const std::size_t n, std::vector<SweepRow> &rows)
    {
      const std::vector<std::string> packed = mpi::gather_bytes(local.bytes);
      if (mpi::rank() != 0)
        {
          ByteUnpacker in(local.bytes);
          while (!in.done())
            rows.push_back(unpack(in).second);
          return;
        }
      rows.assign(n, SweepRow());
      std::vector<bool> seen(n, false);
      for (const std::string &bytes : packed)
        {
          ByteUnpacker in(bytes);
          while (!in.done())
            {
              auto [index, row] = unpack(in);
              if (index >= n || seen[index])
                throw std::runtime_error("cdea sweep: bad row index in the gather");
              seen[index] = true;
              rows[index] = std::move(row);
            }
        }
      if (std::find(seen.begin(), seen.end(), false) != seen.end())
        throw std::runtime_error("cdea sweep: a row is missing after the gather");
    }
  } // namespace

  SweepMap compute_sweep_map(const Parameters &p, const Scene &base,
                             const SweepSettings &settings,
                             const std::function<void(std::size_t)> &on_points)
  {
    RowContext context{base,
                       settings,
                       fe_discretization(p),
                       newton_settings(p),
                       sweep_stepping_settings(p),
                       0.};
    SweepMap map;
    map.settings = settings;
    // The same on every rank (same input, same arithmetic).
    map.zero_voltage_displacement =
      zero_voltage_displacement(base, context.disc, context.newton, context.stepping);
    context.zero_voltage_displacement = map.zero_voltage_displacement;

    const std::size_t n = settings.ring_edge_values.size(), m = settings.outer_voltages.size();
    const std::vector<std::size_t> mine = rows_of_rank(n, mpi::rank(), mpi::size());
    const bool                     distributed = mpi::size() > 1;
    ProgressRelay progress(std::uint64_t(n - mine.size()) * m, on_points);
    BytePacker    local;
    for (const std::size_t i : mine)
      {
        SweepRow row = map_row(context, settings.ring_edge_values[i], progress);
        progress.end_of_row();
        if (distributed)
          pack(local, i, row);
        else
          map.rows.push_back(std::move(row));
      }
    progress.finish();
    if (distributed)
      gather_rows(local, n, map.rows);
    return map;
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
