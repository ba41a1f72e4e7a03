#pragma once
// The data files of `cdea fit` besides displacement-voltage points
// (doc/materials.md, "Fits"): DMA tables and creep curves, recognised by the
// columns of their header line, and the CSV reading all three kinds share.

#include <functional>
#include <istream>
#include <string>
#include <vector>

namespace cdea
{
  /// Fields of one CSV line, blanks around each removed; a ',' at the end of
  /// the line ends in an empty field.
  std::vector<std::string> csv_fields(const std::string &line);

  /// Line @p number (from 1) of a data file without its comment ('#'), line
  /// end and (on the first line) UTF-8 byte order mark.
  std::string csv_content(std::string line, unsigned int number);

  /// The bytes of data file @p file (a regular file of at most 64 MB);
  /// InputError naming it if it cannot be read.
  std::string read_data_file(const std::string &file);

  /// The fields of the header line of CSV text @p in (the first line that is
  /// not blank or a comment; none if there is none), read to that line.
  std::vector<std::string> csv_header(std::istream &in);

  /// What a data file holds, by the columns of its header line.
  enum class FitDataKind
  {
    displacement_voltage, ///< V1_kV .. VN_kV, displacement_mm: equilibrium points
    creep,                ///< time_s, V1_kV .. VN_kV, displacement_mm: a time run
    dma                   ///< frequency_Hz, storage_kPa, loss_kPa: the small-strain moduli
  };

  /// The kind of data file @p file by its header line (the first line that
  /// is not blank or a comment): a column frequency_Hz makes it DMA, time_s
  /// creep, anything else displacement-voltage points. InputError if the file
  /// cannot be read.
  FitDataKind fit_data_kind(const std::string &file);
  /// The same from CSV text @p in (read to its header line).
  FitDataKind fit_data_kind(std::istream &in);

  /// A DMA table: frequency (Hz), storage and loss modulus of uniaxial
  /// tension (Pa), weight (of both moduli of a row).
  struct DmaData
  {
    std::vector<double> frequency, storage, loss, weight;
    std::size_t         size() const { return frequency.size(); }
  };

  /// A creep curve: sample times (s) with the ring voltages there (V), the
  /// displacement |z(A) - z(B)| (m) and weight.
  struct CreepData
  {
    std::vector<double>              times;
    std::vector<std::vector<double>> voltages;
    std::vector<double>              displacement, weight;
    std::size_t                      size() const { return times.size(); }
  };

  /// Reads a DMA table (a regular file of at most 64 MB, at most 10000
  /// rows): header frequency_Hz, storage_kPa, loss_kPa and optionally weight
  /// in any order; frequencies above 0, storage above 0, loss from 0,
  /// weights above 0. Throws InputError naming the file, line and column.
  DmaData read_dma_data(const std::string &file);
  DmaData read_dma_data(std::istream &in, const std::string &name);

  /// Reads a creep curve: header time_s, V1_kV .. VN_kV (@p n_rings),
  /// displacement_mm and optionally weight; times from 0 increasing
  /// strictly, voltages from 0 to @p voltage_ceiling (V), displacements from
  /// 0, weights above 0. Throws InputError naming the file, line and column.
  CreepData read_creep_data(const std::string &file, unsigned int n_rings,
                            double voltage_ceiling);
  CreepData read_creep_data(std::istream &in, const std::string &name, unsigned int n_rings,
                            double voltage_ceiling);

  /// A CSV table of numbers by column name: @p known tells which names a
  /// header may have (@p expected describes them in the message for another),
  /// each once, @p required must be there. Rows as read, by header position.
  /// At most @p max_rows rows (a fit evaluates every row at every iteration).
  struct CsvTable
  {
    std::vector<std::string>         names;
    std::vector<std::vector<double>> rows;
    std::vector<unsigned int>        lines; ///< the file's line of each row
    unsigned int                     header_line = 0;
    /// The position of @p name in a row (-1: not a column).
    int column(const std::string &name) const;
  };
  CsvTable read_csv_table(std::istream &in, const std::string &name,
                          const std::function<bool(const std::string &)> &known,
                          const std::string &expected, const std::vector<std::string> &required,
                          std::size_t max_rows = 10000);
} // namespace cdea
