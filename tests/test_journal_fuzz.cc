// Fuzzing of the journal reader in-process: the journal of a killed run
// (fork, ResultsFile, SIGKILL) damaged at random (bytes flipped, cut,
// zeroed, inserted, repeated, swapped, a second journal appended, record
// payloads changed with their CRC made to fit again, length and count
// fields made huge, other magics) and handed to recover_results() as
// `cdea recover` does. Every case must end in a Recovery or an OutputError
// (no other exception, no crash, no hang: ctest's timeout); a file it writes
// must be readable HDF5 with as many /summary rows as it reports; a damaged
// journal is kept, an intact one removed.
// Usage: test_journal_fuzz [CASES] [SEED] (ctest: 500 cases, seed 7, about
// 2 s).

#include <cdea/output/results_file.h>
#include <cdea/output/safe_files.h>

#include <hdf5.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <random>
#include <string>

#include "check.h"
#include "results_file_demo.h"

using namespace results_file_demo;
namespace fs = std::filesystem;

namespace
{
  std::string read_bytes(const std::string &path)
  {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }

  void write_bytes(const std::string &path, const std::string &bytes)
  {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  }

  /// The journal of a run killed after @p steps steps (no destructor ran).
  std::string killed_journal(const std::string &path, const unsigned int steps)
  {
    std::cout.flush();
    const pid_t child = fork();
    if (child == 0)
      {
        cdea::ResultsFile file(path, parameters_text, 2, demo_root_attributes);
        file.describe_column("volume_mm3", "mm3", "enclosed volume");
        for (unsigned int i = 0; i < steps; ++i)
          file.append(demo_summary(i), demo_fields(i), demo_extra(i));
        file.write_onset(demo_onset());
        file.set_summary_attribute("limit_point_kV", {6.5, 7.25});
        raise(SIGKILL);
        _exit(0);
      }
    int status = 0;
    waitpid(child, &status, 0);
    const std::string bytes = read_bytes(path + ".journal");
    fs::remove(path + ".journal");
    fs::remove(path + ".lock");
    fs::remove(cdea::sibling_name(path, ".partial"));
    return bytes;
  }

  std::uint32_t crc32(const char *data, const std::size_t n)
  {
    std::uint32_t crc = 0xFFFFFFFFu;
    for (std::size_t i = 0; i < n; ++i)
      {
        crc ^= static_cast<unsigned char>(data[i]);
        for (int k = 0; k < 8; ++k)
          crc = (crc & 1u) ? 0xEDB88320u ^ (crc >> 1) : crc >> 1;
      }
    return ~crc;
  }

  /// Offsets of the records (type byte) after the 8-byte magic.
  std::vector<std::size_t> records(const std::string &j)
  {
    std::vector<std::size_t> at;
    for (std::size_t p = 8; p + 9 <= j.size();)
      {
        std::uint32_t length = 0;
        std::memcpy(&length, j.data() + p + 1, 4);
        if (p + 9 + length > j.size())
          break;
        at.push_back(p);
        p += 9 + length;
      }
    return at;
  }

  /// One record's payload changed, its CRC recomputed: the decoder sees it.
  void change_payload(std::string &j, std::mt19937 &rng)
  {
    const auto at = records(j);
    if (at.empty())
      return;
    const std::size_t r = at[rng() % at.size()];
    std::uint32_t     length = 0;
    std::memcpy(&length, j.data() + r + 1, 4);
    if (length == 0)
      return;
    const std::size_t pos = r + 5 + rng() % length;
    switch (rng() % 3)
      {
        case 0:
          j[pos] = char(rng());
          break;
        case 1: // a count or length field made huge
          {
            const std::uint64_t huge =
              rng() % 2 ? ~std::uint64_t(0) : (std::uint64_t(1) << (40 + rng() % 23));
            const std::size_t n = std::min<std::size_t>(8, r + 5 + length - pos);
            std::memcpy(&j[pos], &huge, n);
            break;
          }
        default:
          j[r] = char(1 + rng() % 6); // another record type
      }
    const std::uint32_t crc = crc32(j.data() + r, 5 + length);
    std::memcpy(&j[r + 5 + length], &crc, 4);
  }

  std::string mutate(std::string j, std::mt19937 &rng, const std::string &base)
  {
    const auto pick = [&](const std::size_t n) { return n ? std::size_t(rng() % n) : 0; };
    for (unsigned int k = 0, n = 1 + rng() % 3; k < n; ++k)
      switch (rng() % 11)
        {
          case 0: // bytes flipped
            for (unsigned int i = 0, m = 1 + rng() % 8; i < m && !j.empty(); ++i)
              j[pick(j.size())] ^= char(1 + rng() % 255);
            break;
          case 1:
            j.resize(pick(j.size() + 1));
            break;
          case 2: // a range zeroed
            if (!j.empty())
              {
                const std::size_t a = pick(j.size());
                std::fill(j.begin() + long(a),
                          j.begin() + long(std::min(j.size(), a + 1 + pick(4096))), '\0');
              }
            break;
          case 3: // random bytes inserted
            {
              std::string noise(1 + pick(64), '\0');
              for (char &c : noise)
                c = char(rng());
              j.insert(pick(j.size() + 1), noise);
              break;
            }
          case 4: // a range repeated
            if (!j.empty())
              {
                const std::size_t a = pick(j.size()), b = std::min(j.size(), a + 1 + pick(20000));
                j.insert(b, j.substr(a, b - a));
              }
            break;
          case 5:
            j += base; // a second journal appended to it
            break;
          case 6:
            j += base.substr(8); // its records again, without the magic
            break;
          case 7:
          case 8:
            change_payload(j, rng);
            break;
          case 9: // another magic
            j.replace(0, std::min<std::size_t>(8, j.size()),
                      rng() % 2 ? std::string("CDEAJNL1") : std::string("XXXXXXXX"));
            break;
          default: // two ranges swapped
            if (j.size() > 2)
              {
                const std::size_t a = pick(j.size() / 2), b = j.size() / 2 + pick(j.size() / 2);
                std::swap(j[a], j[b]);
              }
        }
    return j;
  }

  /// Rows of /summary/stage in @p path, or -1 if it cannot be read.
  long rows_of(const std::string &path)
  {
    H5E_auto2_t func = nullptr;
    void       *data = nullptr;
    H5Eget_auto2(H5E_DEFAULT, &func, &data);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    long        rows = -1;
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file >= 0)
      {
        const hid_t set = H5Dopen2(file, "/summary/stage", H5P_DEFAULT);
        if (set >= 0)
          {
            const hid_t space = H5Dget_space(set);
            hsize_t     n     = 0;
            if (H5Sget_simple_extent_dims(space, &n, nullptr) == 1)
              rows = long(n);
            H5Sclose(space);
            H5Dclose(set);
          }
        H5Fclose(file);
      }
    H5Eset_auto2(H5E_DEFAULT, func, data);
    return rows;
  }
} // namespace

CDEA_TEST_MAIN(int argc, char **argv)
{
  const unsigned int cases = argc > 1 ? unsigned(std::stoul(argv[1])) : 500;
  const unsigned int seed  = argc > 2 ? unsigned(std::stoul(argv[2])) : 7;
  const fs::path     dir   = "test_journal_fuzz_out";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string base = killed_journal((dir / "base.h5").string(), 6);
  check(base.size() > 1000, "a killed run's journal to damage");

  unsigned int recovered = 0, damaged = 0, nothing = 0, refused = 0, failed = 0;
  for (unsigned int c = 0; c < cases; ++c)
    {
      std::mt19937      rng(seed * 1000003u + c);
      const std::string path    = (dir / ("case" + std::to_string(c) + ".h5")).string();
      const std::string journal = path + ".journal";
      write_bytes(journal, mutate(base, rng, base));
      std::string problem;
      try
        {
          const cdea::Recovery r = cdea::recover_results(path, true);
          if (!r.file.empty() && rows_of(r.file) != long(r.steps))
            problem = "the recovered file " + r.file + " has " +
                      std::to_string(rows_of(r.file)) + " rows, reported " +
                      std::to_string(r.steps);
          else if (r.damaged != fs::exists(journal))
            problem = std::string("a ") + (r.damaged ? "damaged journal removed" :
                                                       "journal kept without damage");
          (r.damaged ? damaged : r.steps ? recovered : nothing) += 1;
        }
      catch (const cdea::OutputError &)
        {
          ++refused; // a journal that cannot be read: a message, nothing written
        }
      catch (const std::exception &e)
        {
          problem = std::string("an exception other than OutputError: ") + e.what();
        }
      if (!problem.empty())
        {
          ++failed;
          std::cout << "FAIL case " << c << ": " << problem << '\n';
        }
      for (const auto &entry : fs::directory_iterator(dir))
        if (entry.path().filename().string().rfind("case", 0) == 0)
          fs::remove_all(entry.path());
    }
  std::cout << cases << " damaged journals (seed " << seed << "): " << recovered
            << " recovered whole, " << damaged << " damaged (readable part written), "
            << nothing << " with no step, " << refused << " refused with a message, " << failed
            << " failed\n";
  check(failed == 0, "every damaged journal recovered, reported or refused");
  fs::remove_all(dir);
  return cdea_test::finish();
}
