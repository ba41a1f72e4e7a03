#include <cdea/output/hdf5_support.h>

#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace cdea::hdf5
{
  namespace
  {
    herr_t collect_error(unsigned int, const H5E_error2_t *err, void *data)
    {
      auto *messages = static_cast<std::vector<std::string> *>(data);
      if (err->desc != nullptr && err->desc[0] != '\0')
        messages->emplace_back(err->desc);
      return 0;
    }

    /// Memory grows in steps of this many bytes (the core driver's increment).
    constexpr std::size_t memory_increment = 1 << 20;
  } // namespace

  ErrorPrintingOff::ErrorPrintingOff()
  {
    H5Eget_auto2(H5E_DEFAULT, &old_func, &old_data);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }

  ErrorPrintingOff::~ErrorPrintingOff() { H5Eset_auto2(H5E_DEFAULT, old_func, old_data); }

  void create_parent_directory(const std::string &path)
  {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    std::error_code             error;
    if (!parent.empty() && (std::filesystem::create_directories(parent, error), error))
      throw std::runtime_error("cannot write '" + path + "': cannot create directory '" +
                               parent.string() + "': " + error.message());
  }

  // Innermost and outermost descriptions of the stack; an innermost entry
  // that wraps a system error keeps only that error's text.
  std::string error_text()
  {
    std::vector<std::string> messages; // innermost first
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, collect_error, &messages);
    H5Eclear2(H5E_DEFAULT);
    if (messages.empty())
      return "unknown HDF5 error";
    std::string       reason = messages.front();
    const std::string tag    = "error message = '";
    const auto        begin  = reason.find(tag);
    if (begin != std::string::npos)
      {
        const auto end = reason.find('\'', begin + tag.size());
        if (end != std::string::npos)
          reason = reason.substr(begin + tag.size(), end - begin - tag.size());
      }
    for (char &c : reason)
      if (c == '\n')
        c = ' ';
    if (messages.size() > 1 && messages.back() != reason)
      reason += " (HDF5: " + messages.back() + ")";
    return reason;
  }

  void Writer::fail(const std::string &what) const
  {
    throw std::runtime_error(context + ": " + what + " failed: " + error_text());
  }

  void Writer::write_attribute(const hid_t object, const std::string &name, const hid_t file_type,
                               const hid_t memory_type, const hid_t space,
                               const void *data) const
  {
    const htri_t exists = H5Aexists(object, name.c_str());
    check_status(exists, "H5Aexists(" + name + ")");
    if (exists > 0)
      check_status(H5Adelete(object, name.c_str()), "H5Adelete(" + name + ")");
    Handle attribute(check(H5Acreate2(object, name.c_str(), file_type, space, H5P_DEFAULT,
                                      H5P_DEFAULT),
                           "H5Acreate2(" + name + ")"),
                     H5Aclose);
    check_status(H5Awrite(attribute, memory_type, data), "H5Awrite(" + name + ")");
  }

  Handle Writer::text_type() const
  {
    Handle type(check(H5Tcopy(H5T_C_S1), "H5Tcopy"), H5Tclose);
    check_status(H5Tset_size(type, H5T_VARIABLE), "H5Tset_size");
    check_status(H5Tset_cset(type, H5T_CSET_UTF8), "H5Tset_cset");
    return type;
  }

  void Writer::string_attribute(const hid_t object, const std::string &name,
                                const std::string &value) const
  {
    const Handle type = text_type();
    Handle      space(check(H5Screate(H5S_SCALAR), "H5Screate"), H5Sclose);
    const char *pointer = value.c_str();
    write_attribute(object, name, type, type, space, &pointer);
  }

  void Writer::int_attribute(const hid_t object, const std::string &name, const int value) const
  {
    Handle space(check(H5Screate(H5S_SCALAR), "H5Screate"), H5Sclose);
    write_attribute(object, name, H5T_STD_I32LE, H5T_NATIVE_INT, space, &value);
  }

  void Writer::double_attribute(const hid_t object, const std::string &name,
                                const double value) const
  {
    Handle space(check(H5Screate(H5S_SCALAR), "H5Screate"), H5Sclose);
    write_attribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, space, &value);
  }

  void Writer::double_array_attribute(const hid_t object, const std::string &name,
                                      const std::vector<double> &values, const unsigned int rows,
                                      const unsigned int columns) const
  {
    Handle space;
    if (values.empty())
      space = Handle(check(H5Screate(H5S_NULL), "H5Screate"), H5Sclose);
    else if (rows > 0)
      {
        const hsize_t dims[2] = {rows, columns};
        space = Handle(check(H5Screate_simple(2, dims, nullptr), "H5Screate_simple"), H5Sclose);
      }
    else
      {
        const hsize_t dims[1] = {values.size()};
        space = Handle(check(H5Screate_simple(1, dims, nullptr), "H5Screate_simple"), H5Sclose);
      }
    // HDF5 wants a buffer even for an empty (null) dataspace.
    static const double nothing = 0.;
    write_attribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, space,
                    values.empty() ? &nothing : values.data());
  }

  void Writer::describe(const hid_t object, const std::string &unit,
                        const std::string &description) const
  {
    string_attribute(object, "unit", unit);
    string_attribute(object, "description", description);
  }

  Handle Writer::write_dataset(const hid_t parent, const std::string &name,
                               const hid_t file_type, const hid_t memory_type,
                               const std::vector<hsize_t> &dims, const void *data,
                               const bool empty) const
  {
    Handle space(check(dims.empty() ? H5Screate(H5S_SCALAR) :
                                      H5Screate_simple(int(dims.size()), dims.data(), nullptr),
                       "H5Screate"),
                 H5Sclose);
    Handle properties(check(H5Pcreate(H5P_DATASET_CREATE), "H5Pcreate"), H5Pclose);
    check_status(H5Pset_obj_track_times(properties, false), "H5Pset_obj_track_times");
    Handle set(check(H5Dcreate2(parent, name.c_str(), file_type, space, H5P_DEFAULT, properties,
                                H5P_DEFAULT),
                     "H5Dcreate2(" + name + ")"),
               H5Dclose);
    if (!empty)
      check_status(H5Dwrite(set, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
                   "H5Dwrite(" + name + ")");
    return set;
  }

  void Writer::double_dataset(const hid_t parent, const std::string &name,
                              const std::vector<hsize_t> &dims, const std::vector<double> &values,
                              const std::string &unit, const std::string &description) const
  {
    const Handle set = write_dataset(parent, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, dims,
                                     values.data(), values.empty());
    describe(set, unit, description);
  }

  void Writer::int_dataset(const hid_t parent, const std::string &name,
                           const std::vector<int> &values, const std::string &description) const
  {
    const Handle set = write_dataset(parent, name, H5T_STD_I32LE, H5T_NATIVE_INT,
                                     {values.size()}, values.data(), values.empty());
    describe(set, "1", description);
  }

  void Writer::string_dataset(const hid_t parent, const std::string &name,
                              const std::vector<std::string> &values,
                              const std::string              &description) const
  {
    std::vector<const char *> pointers;
    for (const std::string &s : values)
      pointers.push_back(s.c_str());
    const Handle type = text_type();
    const Handle set =
      write_dataset(parent, name, type, type, {values.size()}, pointers.data(), values.empty());
    describe(set, "", description);
  }

  void Writer::group(const hid_t parent, const std::string &name) const
  {
    Handle properties(check(H5Pcreate(H5P_GROUP_CREATE), "H5Pcreate"), H5Pclose);
    check_status(H5Pset_obj_track_times(properties, false), "H5Pset_obj_track_times");
    Handle created(check(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, properties, H5P_DEFAULT),
                         "H5Gcreate2(" + name + ")"),
                   H5Gclose);
  }

  Handle create_memory_file(const std::string &context, const bool track_times)
  {
    const Writer w(context);
    Handle       fapl(w.check(H5Pcreate(H5P_FILE_ACCESS), "H5Pcreate"), H5Pclose);
    w.check_status(H5Pset_fapl_core(fapl, memory_increment, false), "H5Pset_fapl_core");
    Handle fcpl(w.check(H5Pcreate(H5P_FILE_CREATE), "H5Pcreate"), H5Pclose);
    if (!track_times)
      w.check_status(H5Pset_obj_track_times(fcpl, false), "H5Pset_obj_track_times");
    // The name only identifies the file inside this process (nothing is
    // written to it), and HDF5 refuses two open files of one name.
    static unsigned long long count = 0;
    const std::string name = "cdea-memory-file-" + std::to_string(++count);
    return Handle(w.check(H5Fcreate(name.c_str(), H5F_ACC_TRUNC, fcpl, fapl), "H5Fcreate"),
                  H5Fclose);
  }

  std::size_t file_image_size(const hid_t file, const std::string &context)
  {
    const Writer w(context);
    w.check_status(H5Fflush(file, H5F_SCOPE_LOCAL), "H5Fflush");
    const ssize_t size = H5Fget_file_image(file, nullptr, 0);
    w.check_status(size < 0 ? -1 : 0, "H5Fget_file_image");
    return std::size_t(size);
  }

  std::vector<char> file_image(const hid_t file, const std::string &context)
  {
    const Writer      w(context);
    std::vector<char> image(file_image_size(file, context));
    const ssize_t     got = H5Fget_file_image(file, image.data(), image.size());
    w.check_status(got < 0 ? -1 : 0, "H5Fget_file_image");
    image.resize(std::size_t(got));
    return image;
  }
} // namespace cdea::hdf5
