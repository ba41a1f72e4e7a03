#include <cdea/output/hdf5_support.h>
#include <cdea/output/hdf5_writer.h>

#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace cdea
{
  using hdf5::Handle;

  struct Hdf5Writer::Impl
  {
    std::string            target, temporary;
    hdf5::ErrorPrintingOff quiet;
    Handle                 file;

    /// The result of an HDF5 call (an id or a status), which fails when negative.
    template <typename Result>
    Result checked(const Result result, const std::string &what) const
    {
      if (result < 0)
        throw std::runtime_error("cannot write '" + target + "': " + what + " failed: " +
                                 hdf5::error_text());
      return result;
    }

    /// A dataspace of @p dims (scalar when empty).
    Handle space(const std::vector<hsize_t> &dims) const
    {
      return Handle(checked(dims.empty() ? H5Screate(H5S_SCALAR) :
                                           H5Screate_simple(int(dims.size()), dims.data(), nullptr),
                            "H5Screate"),
                    H5Sclose);
    }

    /// Variable-length UTF-8 strings.
    Handle text_type() const
    {
      Handle type(checked(H5Tcopy(H5T_C_S1), "H5Tcopy"), H5Tclose);
      checked(H5Tset_size(type, H5T_VARIABLE), "H5Tset_size");
      checked(H5Tset_cset(type, H5T_CSET_UTF8), "H5Tset_cset");
      return type;
    }

    void put_attribute(const std::string &object, const std::string &name, const hid_t stored,
                       const hid_t in_memory, const std::vector<hsize_t> &dims, const void *data)
    {
      Handle owner(checked(H5Oopen(file, object.c_str(), H5P_DEFAULT), "H5Oopen(" + object + ")"),
                   H5Oclose);
      Handle where = space(dims);
      Handle attribute(checked(H5Acreate2(owner, name.c_str(), stored, where, H5P_DEFAULT,
                                          H5P_DEFAULT),
                               "H5Acreate2(" + name + ")"),
                       H5Aclose);
      checked(H5Awrite(attribute, in_memory, data), "H5Awrite(" + name + ")");
    }

    void put_dataset(const std::string &path, const hid_t stored, const hid_t in_memory,
                     const std::vector<hsize_t> &dims, const void *data, const bool empty)
    {
      Handle properties(checked(H5Pcreate(H5P_DATASET_CREATE), "H5Pcreate"), H5Pclose);
      checked(H5Pset_obj_track_times(properties, false), "H5Pset_obj_track_times");
      Handle where = space(dims);
      Handle set(checked(H5Dcreate2(file, path.c_str(), stored, where, H5P_DEFAULT, properties,
                                    H5P_DEFAULT),
                         "H5Dcreate2(" + path + ")"),
                 H5Dclose);
      if (!empty)
        checked(H5Dwrite(set, in_memory, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
                       "H5Dwrite(" + path + ")");
    }

    void describe(const std::string &path, const std::string &unit, const std::string &text)
    {
      const Handle type = text_type();
      for (const auto &[name, value] : {std::pair{"unit", &unit}, std::pair{"description", &text}})
        {
          const char *p = value->c_str();
          put_attribute(path, name, type, type, {}, &p);
        }
    }
  };

  Hdf5Writer::Hdf5Writer(const std::string &path)
    : impl(std::make_unique<Impl>())
    , target(path)
  {
    impl->target    = path;
    impl->temporary = path + ".tmp" + std::to_string(::getpid());
    hdf5::create_parent_directory(path);
    Handle creation(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
    if (creation >= 0)
      H5Pset_obj_track_times(creation, false);
    Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
#if H5_VERSION_GE(1, 10, 7)
    if (access >= 0)
      H5Pset_file_locking(access, false, true);
#endif
    const hid_t id = H5Fcreate(impl->temporary.c_str(), H5F_ACC_TRUNC,
                               creation >= 0 ? hid_t(creation) : H5P_DEFAULT,
                               access >= 0 ? hid_t(access) : H5P_DEFAULT);
    if (id < 0)
      throw std::runtime_error("cannot create '" + path + "': " + hdf5::error_text());
    impl->file = Handle(id, H5Fclose);
  }

  Hdf5Writer::~Hdf5Writer()
  {
    if (impl && impl->file.get() >= 0)
      {
        impl->file.reset();
        std::error_code ignored;
        std::filesystem::remove(impl->temporary, ignored);
      }
  }

  void Hdf5Writer::attribute(const std::string &object, const std::string &name,
                             const std::string &value)
  {
    const Handle type = impl->text_type();
    const char  *p    = value.c_str();
    impl->put_attribute(object, name, type, type, {}, &p);
  }

  void Hdf5Writer::attribute(const std::string &object, const std::string &name, const double value)
  {
    impl->put_attribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {}, &value);
  }

  void Hdf5Writer::attribute(const std::string &object, const std::string &name, const int value)
  {
    impl->put_attribute(object, name, H5T_STD_I32LE, H5T_NATIVE_INT, {}, &value);
  }

  void Hdf5Writer::attribute(const std::string &object, const std::string &name,
                             const std::vector<double> &values)
  {
    impl->put_attribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {values.size()},
                        values.data());
  }

  void Hdf5Writer::group(const std::string &path)
  {
    Handle properties(impl->checked(H5Pcreate(H5P_GROUP_CREATE), "H5Pcreate"), H5Pclose);
    impl->checked(H5Pset_obj_track_times(properties, false), "H5Pset_obj_track_times");
    Handle g(impl->checked(H5Gcreate2(impl->file, path.c_str(), H5P_DEFAULT, properties,
                                      H5P_DEFAULT),
                           "H5Gcreate2(" + path + ")"),
             H5Gclose);
  }

  void Hdf5Writer::dataset(const std::string &path, const std::vector<std::size_t> &dims,
                           const std::vector<double> &values, const std::string &unit,
                           const std::string &description)
  {
    const std::vector<hsize_t> h(dims.begin(), dims.end());
    impl->put_dataset(path, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, h, values.data(), values.empty());
    impl->describe(path, unit, description);
  }

  void Hdf5Writer::dataset(const std::string &path, const std::vector<int> &values,
                           const std::string &description)
  {
    impl->put_dataset(path, H5T_STD_I32LE, H5T_NATIVE_INT, {values.size()}, values.data(),
                      values.empty());
    impl->describe(path, "1", description);
  }

  void Hdf5Writer::dataset(const std::string &path, const std::vector<std::string> &values,
                           const std::string &description)
  {
    std::vector<const char *> pointers;
    for (const auto &s : values)
      pointers.push_back(s.c_str());
    const Handle type = impl->text_type();
    impl->put_dataset(path, type, type, {values.size()}, pointers.data(), values.empty());
    impl->describe(path, "", description);
  }

  void Hdf5Writer::commit()
  {
    impl->checked(H5Fflush(impl->file, H5F_SCOPE_LOCAL), "H5Fflush");
    impl->file.reset();
    std::error_code error;
    std::filesystem::rename(impl->temporary, impl->target, error);
    if (error)
      {
        std::filesystem::remove(impl->temporary, error);
        throw std::runtime_error("cannot write '" + impl->target + "': renaming the new file "
                                 "onto it failed: " + error.message());
      }
  }
} // namespace cdea
