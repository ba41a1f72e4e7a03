#include <cdea/base/file_reading.h>
#include <cdea/base/run_control.h>
#include <cdea/model/output_fields.h>
#include <cdea/output/journal.h>
#include <cdea/output/safe_files.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdint>
#include <cstring>

namespace cdea
{
  namespace
  {
    // Format 2: the internal variables of the law named in each step record.
    constexpr char magic[8]        = {'C', 'D', 'E', 'A', 'J', 'N', 'L', '2'};
    constexpr char magic_format1[8] = {'C', 'D', 'E', 'A', 'J', 'N', 'L', '1'};

    enum RecordType : unsigned char
    {
      start_record             = 1,
      describe_column_record   = 2,
      append_record            = 3,
      onset_record             = 4, ///< read only: journals of earlier versions
      summary_attribute_record = 5, ///< read only: journals of earlier versions
      attribute_record         = 6  ///< a /summary attribute as the file holds it
    };

    // CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320).
    std::uint32_t crc32(const char *data, const std::size_t n, std::uint32_t crc = 0)
    {
      static const std::array<std::uint32_t, 256> table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t i = 0; i < 256; ++i)
          {
            std::uint32_t c = i;
            for (int k = 0; k < 8; ++k)
              c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            t[i] = c;
          }
        return t;
      }();
      crc = ~crc;
      for (std::size_t i = 0; i < n; ++i)
        crc = table[(crc ^ static_cast<unsigned char>(data[i])) & 0xFFu] ^ (crc >> 8);
      return ~crc;
    }

    class Encoder
    {
    public:
      std::string bytes;
      template <typename T>
      void raw(const T &x)
      {
        bytes.append(reinterpret_cast<const char *>(&x), sizeof(T));
      }
      void u32(const std::uint32_t x) { raw(x); }
      void f64(const double x) { raw(x); }
      void str(const std::string &s)
      {
        u64(s.size());
        bytes += s;
      }
      void str(const char *s)
      {
        const std::size_t n = std::strlen(s);
        u64(n);
        bytes.append(s, n);
      }
      void u64(const std::uint64_t x) { raw(x); }
      void doubles(const std::vector<double> &v)
      {
        u64(v.size());
        bytes.append(reinterpret_cast<const char *>(v.data()), v.size() * sizeof(double));
      }
      void ints(const std::vector<int> &v)
      {
        u64(v.size());
        bytes.append(reinterpret_cast<const char *>(v.data()), v.size() * sizeof(int));
      }
    };

    /// Reads what Encoder wrote; a payload that ends early throws (it
    /// cannot, after the CRC check, unless the journal is of another build).
    class Decoder
    {
    public:
      Decoder(const char *p, const std::size_t n)
        : p(p)
        , end(p + n)
      {}
      template <typename T>
      T raw()
      {
        need(sizeof(T));
        T x;
        std::memcpy(&x, p, sizeof(T));
        p += sizeof(T);
        return x;
      }
      std::uint32_t u32() { return raw<std::uint32_t>(); }
      std::uint64_t u64() { return raw<std::uint64_t>(); }
      double        f64() { return raw<double>(); }
      std::string   str()
      {
        const std::size_t n = u64();
        need(n);
        std::string s(p, n);
        p += n;
        return s;
      }
      std::vector<double> doubles()
      {
        const std::size_t n = count(sizeof(double));
        std::vector<double> v(n);
        std::memcpy(v.data(), p, n * sizeof(double));
        p += n * sizeof(double);
        return v;
      }
      std::vector<int> ints()
      {
        const std::size_t n = count(sizeof(int));
        std::vector<int> v(n);
        std::memcpy(v.data(), p, n * sizeof(int));
        p += n * sizeof(int);
        return v;
      }

    private:
      const char *p, *end;
      void        need(const std::size_t n) const
      {
        if (std::size_t(end - p) < n)
          throw OutputError("journal record shorter than its content");
      }
      /// A count of items of @p size bytes that the rest of the record holds
      /// (checked without n * size, which a damaged count would overflow).
      std::size_t count(const std::size_t size)
      {
        const std::size_t n = u64();
        if (n > std::size_t(end - p) / size)
          throw OutputError("journal record shorter than its content");
        return n;
      }
    };

    /// A record: its type and where its payload is in Parsed::data (a
    /// journal is held once in memory, not copied record by record).
    struct Record
    {
      unsigned char type;
      std::size_t   offset, length;
    };

    struct Parsed
    {
      std::string         data;
      std::vector<Record> records;
      std::size_t         dropped_bytes = 0;
      std::size_t         damaged_at    = no_damage;
    };

    constexpr std::size_t frame = 1 + 4 + 4; // type, length, CRC

    /// Whether the bytes from @p at on, which do not hold a valid record, are
    /// a record cut short at the end (a kill or a full disk during its
    /// write) rather than damage with more records behind it: too few bytes
    /// for a frame, a length reaching past the end that a record of this
    /// journal could have (about the size of its step records, or of a step
    /// of at most 1e5 samples before the first), or a record ending exactly
    /// at the end.
    bool torn_last_record(const std::string &data, const std::size_t at,
                          const std::size_t largest_step)
    {
      const std::size_t left = data.size() - at;
      if (left < frame)
        return true;
      std::uint32_t length = 0;
      std::memcpy(&length, data.data() + at + 1, 4);
      const unsigned char type = static_cast<unsigned char>(data[at]);
      if (type < start_record || type > attribute_record)
        return false;
      constexpr std::size_t megabyte = std::size_t(1) << 20;
      if (left - frame < length)
        return length <= (largest_step > 0 ? 2 * largest_step : 16 * megabyte) + megabyte;
      return left - frame == length;
    }

    /// The first bytes of a journal: format 2's magic (or the start of it:
    /// a journal cut inside it holds nothing), else it is not read on.
    void check_magic(const std::string &path, const std::string &head)
    {
      if (head.size() >= sizeof(magic) &&
          std::memcmp(head.data(), magic_format1, sizeof(magic)) == 0)
        throw OutputError(path + " was written by an older version of cdea (journal format 1): "
                                 "recover it with that version");
      if (std::memcmp(head.data(), magic, std::min(head.size(), sizeof(magic))) != 0)
        throw OutputError(path + " is not a cdea journal");
    }

    Parsed read_records(const std::string &path)
    {
      // Not through a symbolic link: a journal is cdea's own file.
      ReadOptions options;
      options.follow_links = false;
      options.head_bytes   = sizeof(magic);
      options.check_head   = [&](const std::string &head) { check_magic(path, head); };
      FileRead read        = read_regular_file(path, max_journal_bytes, options);
      if (!read.ok)
        throw OutputError("cannot read the journal " + path + ": " + read.error);
      Parsed             parsed;
      parsed.data        = std::move(read.bytes);
      const std::string &data = parsed.data;
      if (data.size() < sizeof(magic))
        {
          parsed.dropped_bytes = data.size();
          return parsed;
        }
      std::size_t at = sizeof(magic), largest_step = 0;
      while (data.size() - at >= frame)
        {
          std::uint32_t length = 0, crc = 0;
          std::memcpy(&length, data.data() + at + 1, 4);
          if (data.size() - at - frame < length)
            break;
          std::memcpy(&crc, data.data() + at + 5 + length, 4);
          if (crc32(data.data() + at, 5 + length) != crc)
            break;
          if (data[at] == char(start_record) && !parsed.records.empty())
            {
              // A second start: another journal (or this one) appended to it.
              parsed.dropped_bytes = data.size() - at;
              parsed.damaged_at    = at;
              return parsed;
            }
          parsed.records.push_back({static_cast<unsigned char>(data[at]), at + 5, length});
          if (data[at] == char(append_record))
            largest_step = std::max<std::size_t>(largest_step, length);
          at += frame + length;
        }
      parsed.dropped_bytes = data.size() - at;
      if (at < data.size() && !torn_last_record(data, at, largest_step))
        parsed.damaged_at = at;
      return parsed;
    }

    StepSummary decode_summary(Decoder &in)
    {
      StepSummary s;
      s.stage             = static_cast<Stage>(in.raw<std::int32_t>());
      s.load_factor       = in.f64();
      s.voltages          = in.doubles();
      s.mass              = in.f64();
      s.displacement      = in.f64();
      s.stroke            = in.f64();
      s.s2_min            = in.f64();
      s.s2_ring_inner     = in.doubles();
      s.wrinkled          = in.raw<std::uint8_t>() != 0;
      s.newton_iterations = in.u32();
      return s;
    }

    void encode_summary(Encoder &out, const StepSummary &s)
    {
      out.raw(static_cast<std::int32_t>(s.stage));
      out.f64(s.load_factor);
      out.doubles(s.voltages);
      out.f64(s.mass);
      out.f64(s.displacement);
      out.f64(s.stroke);
      out.f64(s.s2_min);
      out.doubles(s.s2_ring_inner);
      out.raw(static_cast<std::uint8_t>(s.wrinkled));
      out.u32(s.newton_iterations);
    }

    /// The fields: those of the table stored in StepFields (in its
    /// order), the law's internal variables with their names, the ring.
    void encode_fields(Encoder &out, const StepFields &fields)
    {
      for (const StepField &row : step_fields())
        if (row.values)
          out.doubles(fields.*row.values);
      out.u64(fields.internal.size());
      for (const InternalField &f : fields.internal)
        {
          out.str(f.name);
          out.str(f.unit);
          out.str(f.description);
          out.doubles(f.values);
        }
      out.ints(fields.ring);
    }

    StepFields decode_fields(Decoder &in)
    {
      StepFields fields;
      for (const StepField &row : step_fields())
        if (row.values)
          fields.*row.values = in.doubles();
      fields.internal.resize(in.u64());
      for (InternalField &f : fields.internal)
        {
          f.name        = in.str();
          f.unit        = in.str();
          f.description = in.str();
          f.values      = in.doubles();
        }
      fields.ring = in.ints();
      return fields;
    }
  } // namespace

  JournalWriter::~JournalWriter() { close(); }

  void JournalWriter::close() noexcept
  {
    if (fd >= 0)
      ::close(fd);
    fd = -1;
  }

  void JournalWriter::open(const std::string &path, const std::string &parameters_text,
                           const unsigned int n_rings,
                           const std::vector<std::pair<std::string, std::string>> &extra)
  {
    close();
    file = path;
    // The flock, held while the journal is open, tells others this journal
    // is live (recover_results() never touches a locked one); it is taken
    // before the journal is emptied.
    // Created new, never through a link: a journal left by an earlier run
    // has been saved and removed before (ResultsFile), and anything else of
    // that name is not ours to empty.
    const int f =
      ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (f < 0)
      throw OutputError("cannot create the journal " + path + ": " +
                        (errno == EEXIST ? std::string("something of that name is in the way "
                                                       "(not a journal cdea can save): remove it") :
                                           std::string(std::strerror(errno))));
    if (::flock(f, LOCK_EX | LOCK_NB) != 0)
      {
        ::close(f);
        throw OutputError("another cdea process is writing the journal " + path);
      }
    fd = f;
    if (::ftruncate(fd, 0) != 0)
      throw OutputError("cannot empty the journal " + path + ": " + std::strerror(errno));
    bytes = 0;
    Encoder out;
    out.bytes.assign(magic, sizeof(magic));
    // A journal cut inside the magic or the first record holds no step: it
    // replays into nothing.
    Encoder start;
    start.str(parameters_text);
    start.u32(n_rings);
    start.u64(extra.size());
    for (const auto &[name, value] : extra)
      {
        start.str(name);
        start.str(value);
      }
    const ssize_t n = ::write(fd, out.bytes.data(), out.bytes.size());
    if (n != ssize_t(out.bytes.size()))
      throw OutputError("cannot write the journal " + path + ": " +
                        std::strerror(n < 0 ? errno : ENOSPC));
    bytes = out.bytes.size();
    described.clear();
    write_record(start_record, start.bytes);
  }

  void JournalWriter::write_record(const unsigned char type, const std::string &payload)
  {
    if (fd < 0)
      throw OutputError("the journal " + file + " is not open");
    std::string record(1, static_cast<char>(type));
    const std::uint32_t length = static_cast<std::uint32_t>(payload.size());
    record.append(reinterpret_cast<const char *>(&length), 4);
    record += payload;
    const std::uint32_t crc = crc32(record.data(), record.size());
    record.append(reinterpret_cast<const char *>(&crc), 4);
    std::size_t done = 0;
    while (done < record.size())
      {
        const ssize_t n = ::pwrite(fd, record.data() + done, record.size() - done,
                                   off_t(bytes + done));
        if (n < 0 && errno == EINTR)
          continue;
        if (n <= 0)
          {
            const int error = n < 0 ? errno : ENOSPC;
            if (::ftruncate(fd, off_t(bytes)) != 0)
              {
                // The torn record fails its check when read back.
              }
            throw OutputError("cannot write the journal " + file + ": " + std::strerror(error));
          }
        done += std::size_t(n);
      }
    bytes += record.size();
  }

  void JournalWriter::describe_column(const std::string &name, const std::string &unit,
                                      const std::string &description)
  {
    Encoder out;
    out.str(name);
    out.str(unit);
    out.str(description);
    write_record(describe_column_record, out.bytes);
  }

  void JournalWriter::append(const StepSummary &summary, const StepFields &fields,
                             const std::vector<NamedColumn> &extra_columns)
  {
    // The table's columns go in as the document names them; a column's
    // description is recorded when it first appears.
    for (const auto &entry : summary.columns)
      if (std::find(described.begin(), described.end(), entry.first) == described.end())
        {
          describe_column(entry.first->name, entry.first->unit.name, entry.first->description);
          described.push_back(entry.first);
        }
    Encoder out;
    encode_summary(out, summary);
    encode_fields(out, fields);
    // As named_columns(): the table's columns in the file's units, then the extra ones.
    out.u64(summary.columns.size() + extra_columns.size());
    for (const auto &[column, value] : summary.columns)
      {
        out.str(column->name);
        out.f64(column->in_file_units(value));
      }
    for (const auto &[name, value] : extra_columns)
      {
        out.str(name);
        out.f64(value);
      }
    write_record(append_record, out.bytes);
  }

  void JournalWriter::summary_attribute(const FileAttribute &attribute)
  {
    Encoder out;
    out.str(attribute.name);
    out.raw(static_cast<std::uint8_t>(attribute.kind));
    out.u64(attribute.dims.size());
    for (const std::size_t d : attribute.dims)
      out.u64(d);
    out.doubles(attribute.values);
    out.str(attribute.text);
    write_record(attribute_record, out.bytes);
  }

  namespace
  {
    std::unique_ptr<ResultsDocument> replay_start(Decoder &in, const std::string &name)
    {
      const std::string text    = in.str();
      const unsigned    n_rings = in.u32();
      const std::size_t n_extra = in.u64();
      std::vector<std::pair<std::string, std::string>> extra;
      for (std::size_t i = 0; i < n_extra; ++i)
        {
          std::string key = in.str();
          extra.emplace_back(std::move(key), in.str());
        }
      return std::make_unique<ResultsDocument>(name, text, n_rings, extra);
    }

    void replay_append(Decoder &in, ResultsDocument &document)
    {
      const StepSummary        summary = decode_summary(in);
      const StepFields         fields  = decode_fields(in);
      std::vector<NamedColumn> columns;
      const std::size_t        n = in.u64();
      for (std::size_t i = 0; i < n; ++i)
        {
          std::string column = in.str();
          columns.emplace_back(std::move(column), in.f64());
        }
      document.append(summary, fields, columns);
    }

    void replay_onset(Decoder &in, ResultsDocument &document)
    {
      OnsetRecord onset;
      onset.found       = in.raw<std::uint8_t>() != 0;
      onset.voltages    = in.doubles();
      onset.radius      = in.f64();
      onset.load_factor = in.f64();
      document.write_onset(onset);
    }

    /// Replays one record after the start into @p replay; false at a step
    /// beyond @p max_steps (the replay ends there).
    bool replay_record(const Record &r, const std::string &data, JournalReplay &replay,
                       const unsigned int max_steps)
    {
      Decoder          in(data.data() + r.offset, r.length);
      ResultsDocument &document = *replay.document;
      switch (r.type)
        {
          case describe_column_record:
            {
              const std::string column = in.str();
              const std::string unit   = in.str();
              document.describe_column(column, unit, in.str());
              return true;
            }
          case append_record:
            if (replay.steps >= max_steps)
              return false;
            replay_append(in, document);
            ++replay.steps;
            return true;
          case onset_record:
            replay_onset(in, document);
            return true;
          case attribute_record:
            {
              FileAttribute a;
              a.name          = in.str();
              const auto kind = in.raw<std::uint8_t>();
              if (kind > static_cast<std::uint8_t>(FileAttribute::Kind::text))
                throw OutputError("an attribute of an unknown kind");
              a.kind                   = static_cast<FileAttribute::Kind>(kind);
              const std::uint64_t rank = in.u64();
              if (rank > 3)
                throw OutputError("an attribute of more than three dimensions");
              for (std::uint64_t k = 0; k < rank; ++k)
                a.dims.push_back(in.u64());
              a.values = in.doubles();
              a.text   = in.str();
              document.set_summary_attribute(a);
              return true;
            }
          case summary_attribute_record:
            {
              const std::string         attribute = in.str();
              const std::vector<double> values    = in.doubles();
              const unsigned int        rows      = in.u32();
              document.set_summary_attribute(attribute, values, rows, in.u32());
              return true;
            }
          default:
            throw OutputError("unknown record type " + std::to_string(int(r.type)));
        }
    }
  } // namespace

  JournalReplay replay_journal(const std::string &path, const std::string &name,
                               const unsigned int max_steps, const bool stop_on_request)
  {
    const Parsed  parsed = read_records(path);
    JournalReplay replay;
    replay.dropped_bytes = parsed.dropped_bytes;
    replay.damaged_at    = parsed.damaged_at;
    for (const Record &r : parsed.records)
      replay.journal_steps += r.type == append_record;
    if (parsed.records.empty() || parsed.records.front().type != start_record)
      return replay;
    try
      {
        for (const Record &r : parsed.records)
          if (r.type == start_record)
            {
              Decoder in(parsed.data.data() + r.offset, r.length);
              replay.document = replay_start(in, name);
            }
          else if (stop_on_request && StopOnSignals::requested() != 0)
            throw RunInterrupted(StopOnSignals::requested());
          else if (!replay_record(r, parsed.data, replay, max_steps))
            break;
      }
    catch (const RunInterrupted &)
      {
        throw;
      }
    catch (const std::invalid_argument &e)
      {
        throw OutputError("the journal " + path + " holds an invalid record: " + e.what());
      }
    catch (const std::exception &e)
      {
        // A record that passes its check but not the replay (another
        // build's journal, or damage the CRC missed): as damage, one line.
        throw OutputError("the journal " + path + " cannot be replayed: " + e.what());
      }
    return replay;
  }
} // namespace cdea
