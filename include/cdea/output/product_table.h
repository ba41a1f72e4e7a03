#pragma once
// The one printer of tables from products (model/product.h): a column per
// row of the table of quantities, each value converted from SI by its row,
// so that a printed table shows the numbers the file and the Python result
// hold. The commands print their tables with it; their banners and lines of
// prose stay their own.

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

namespace cdea
{
  class ProductGroup;
  struct Quantity;

  /// How a column shows a value in its row's unit.
  enum class CellStyle
  {
    fixed,         ///< `digits` decimals
    number,        ///< `digits` significant digits
    fixed_or_dash, ///< fixed, "-" for NaN
    plain,         ///< as the stream prints it, with its precision
    integer,       ///< a whole number
    text,          ///< a text shortened to `digits` characters at a word, "-" if empty
    list,          ///< the values along the last dimension: "a, b unit", `digits` digits
    index          ///< the table row's number from 1 (no value of the row)
  };

  /// A column: the dataset of @p row in the group, right-aligned in @p width
  /// characters (0: as it is) after @p before. A dataset of more than one
  /// dimension gives its @p component'th value of each table row.
  struct TableColumn
  {
    const Quantity *row;
    std::string     header;
    int             width  = 0;
    CellStyle       style  = CellStyle::number;
    int             digits = 6;
    std::string     before = "";
    std::size_t     component = 0;
  };

  /// The header line: each column's header in its width.
  void print_table_header(std::ostream &out, const std::vector<TableColumn> &columns);

  /// Table row @p k: a cell per column, then a line end.
  void print_table_row(std::ostream &out, const ProductGroup &group,
                       const std::vector<TableColumn> &columns, std::size_t k);

  /// The headers, and the cells of row @p k, without the line end (a
  /// command adds to the line).
  void print_table_cells(std::ostream &out, const std::vector<TableColumn> &columns);
  void print_table_cells(std::ostream &out, const ProductGroup &group,
                         const std::vector<TableColumn> &columns, std::size_t k);

  /// The header and the rows @p rows.
  void print_table(std::ostream &out, const ProductGroup &group,
                   const std::vector<TableColumn> &columns, const std::vector<std::size_t> &rows);

  /// About eleven of @p n rows, evenly spaced, the first and the last included.
  std::vector<std::size_t> sampled_rows(std::size_t n);
} // namespace cdea
