#include <cdea/base/format.h>
#include <cdea/model/product.h>
#include <cdea/output/product_table.h>

#include <algorithm>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace cdea
{
  namespace
  {
    /// The cell of @p column in table row @p k.
    std::string cell(std::ostream &out, const ProductGroup &group, const TableColumn &column,
                     const std::size_t k)
    {
      if (column.style == CellStyle::index)
        return std::to_string(k + 1);
      const ProductEntry &e = group.at(*column.row);
      if (column.style == CellStyle::text)
        {
          const std::string &text = e.texts.at(k);
          return text.empty() ? std::string("-") : shorten_at_word(text, column.digits);
        }
      std::size_t stride = 1;
      for (std::size_t d = 1; d < e.dims.size(); ++d)
        stride *= e.dims[d];
      if (column.style == CellStyle::list)
        {
          std::ostringstream s;
          s.precision(column.digits);
          for (std::size_t j = 0; j < stride; ++j)
            s << (j ? ", " : "") << e.value(k * stride + j);
          return s.str() + " " + column.row->unit.name;
        }
      const double x = e.value(k * stride + column.component);
      switch (column.style)
        {
          case CellStyle::fixed:
            return format_fixed(x, column.digits);
          case CellStyle::fixed_or_dash:
            return format_fixed_or_dash(x, column.digits);
          case CellStyle::integer:
            return std::to_string(static_cast<long long>(x));
          case CellStyle::plain:
            {
              std::ostringstream s;
              s.copyfmt(out);
              s.width(0);
              s << x;
              return s.str();
            }
          default:
            return format_number(x, column.digits);
        }
    }
  } // namespace

  void print_table_cells(std::ostream &out, const std::vector<TableColumn> &columns)
  {
    for (const TableColumn &c : columns)
      out << c.before << std::setw(c.width) << c.header;
  }

  void print_table_cells(std::ostream &out, const ProductGroup &group,
                         const std::vector<TableColumn> &columns, const std::size_t k)
  {
    for (const TableColumn &c : columns)
      {
        const std::string text = cell(out, group, c, k);
        out << c.before << std::setw(c.width) << text;
      }
  }

  void print_table_header(std::ostream &out, const std::vector<TableColumn> &columns)
  {
    print_table_cells(out, columns);
    out << '\n';
  }

  void print_table_row(std::ostream &out, const ProductGroup &group,
                       const std::vector<TableColumn> &columns, const std::size_t k)
  {
    print_table_cells(out, group, columns, k);
    out << '\n';
  }

  void print_table(std::ostream &out, const ProductGroup &group,
                   const std::vector<TableColumn> &columns, const std::vector<std::size_t> &rows)
  {
    print_table_header(out, columns);
    for (const std::size_t k : rows)
      print_table_row(out, group, columns, k);
  }

  std::vector<std::size_t> sampled_rows(const std::size_t n)
  {
    std::vector<std::size_t> rows;
    const std::size_t        every = std::max<std::size_t>(1, (n - 1) / 10);
    for (std::size_t k = 0; k < n; k += every)
      rows.push_back(k);
    if (rows.back() != n - 1)
      rows.push_back(n - 1);
    return rows;
  }
} // namespace cdea
