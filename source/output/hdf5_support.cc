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
} // namespace cdea::hdf5
