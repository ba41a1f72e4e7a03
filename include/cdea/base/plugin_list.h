#pragma once
// One registry for every kind of plugin, in the manner of ASPECT's
// PluginList: the material laws (material/law_factory.h), the load terms
// (fe/load_term.h) and the postprocessors (solver/postprocessors.h) are each
// a PluginList of their interface, and a plugin of any of them has the same
// shape, a class with
//
//   static void declare_parameters(ParameterDeclarations &prm);
//     its entries of the parameter file (the interface's default: none);
//   static Pointer create(const Input &input);
//     the plugin made from the parsed parameters (its entries checked:
//     InputError naming the entry and what is allowed); without it, the
//     plugin is constructed from the input (a constructor taking it);
//
// and, where the order of the plugins matters (the postprocessors: each sees
// what the earlier ones wrote), static constexpr int position (default 0).
// It registers itself with one line at the end of its source file, inside
// namespace cdea:
//
//   CDEA_REGISTER_PLUGIN(MembraneLaws, MooneyRivlinLaw, "mooney-rivlin", 0, "description")
//
// The list keeps the plugins by position, then by name: registrations run
// during static initialisation in an order the language leaves open, and the
// order fixes the last bits of every sum the plugins add to. No deal.II.

#include <cdea/base/parameter_declarations.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace cdea
{
  /// The plugins that derive from @p Interface and are made from @p Input.
  template <typename Interface, typename Input,
            typename Pointer = std::unique_ptr<Interface>>
  class PluginList
  {
  public:
    using input_type   = Input;
    using pointer_type = Pointer;

    /// A plugin as CDEA_REGISTER_PLUGIN registers it.
    struct Plugin
    {
      std::string  name;        ///< its name in the parameter file and in messages
      unsigned int flags;       ///< what it supports or where it runs (the list's bits)
      std::string  description; ///< what the documentation says of it
      int          position;    ///< its place in the order (then by name)
      void (*declare_parameters)(ParameterDeclarations &prm);
      Pointer (*create)(const Input &input);
    };

    /// Registers @p plugin; true. Throws std::logic_error if its name is taken.
    static bool register_plugin(const Plugin &plugin)
    {
      std::vector<Plugin> &list = registry();
      if (find(plugin.name))
        throw std::logic_error("two plugins of one kind are registered as '" + plugin.name + "'");
      const auto later = std::find_if(list.begin(), list.end(), [&](const Plugin &p) {
        return p.position > plugin.position ||
               (p.position == plugin.position && p.name > plugin.name);
      });
      list.insert(later, plugin);
      return true;
    }

    /// The registered plugins in their order (by position, then by name).
    static const std::vector<Plugin> &plugins() { return registry(); }

    /// The registered plugin @p name, or nullptr.
    static const Plugin *find(const std::string &name)
    {
      for (const Plugin &p : registry())
        if (p.name == name)
          return &p;
      return nullptr;
    }

    /// The registered names, in order.
    static std::vector<std::string> names()
    {
      std::vector<std::string> list;
      for (const Plugin &p : registry())
        list.push_back(p.name);
      return list;
    }

    /// "'NAME': description" of every plugin, joined by blanks, in order.
    static std::string documentation()
    {
      std::string text;
      for (const Plugin &p : registry())
        text += (text.empty() ? "'" : " '") + p.name + "': " + p.description;
      return text;
    }

    /// Every plugin's entries, plugin by plugin in order.
    static ParameterDeclarations parameters()
    {
      ParameterDeclarations all;
      for (const Plugin &p : registry())
        {
          ParameterDeclarations own;
          p.declare_parameters(own);
          all.append(own);
        }
      return all;
    }

    /// The plugin @p name made from @p input; std::invalid_argument if no
    /// plugin is registered under that name.
    static Pointer create(const std::string &name, const Input &input)
    {
      if (const Plugin *p = find(name))
        return p->create(input);
      throw std::invalid_argument("no plugin is registered as '" + name + "'");
    }

  private:
    static std::vector<Plugin> &registry()
    {
      static std::vector<Plugin> list; // made on first use, by the first registration
      return list;
    }
  };

  /// The create() of the plugin class @p Plugin of @p List: its own, or its
  /// constructor from the input.
  template <typename List, typename Plugin, typename = void>
  struct plugin_creator
  {
    static typename List::pointer_type create(const typename List::input_type &input)
    {
      return typename List::pointer_type(new Plugin(input));
    }
  };

  template <typename List, typename Plugin>
  struct plugin_creator<List, Plugin, std::void_t<decltype(&Plugin::create)>>
  {
    static typename List::pointer_type create(const typename List::input_type &input)
    {
      return Plugin::create(input);
    }
  };

  /// @p Plugin::position, or 0 if the class has none.
  template <typename Plugin, typename = void>
  struct plugin_position
  {
    static constexpr int value = 0;
  };

  template <typename Plugin>
  struct plugin_position<Plugin, std::void_t<decltype(Plugin::position)>>
  {
    static constexpr int value = Plugin::position;
  };
} // namespace cdea

/// Registers the class @p classname as the plugin @p name of the PluginList
/// @p list, with @p flags (the list's bits: what it supports or where it
/// runs) and @p description; one line at the end of the plugin's source
/// file, inside namespace cdea.
#define CDEA_REGISTER_PLUGIN(list, classname, name, flags, description)                        \
  namespace                                                                                  \
  {                                                                                          \
    [[maybe_unused]] const bool classname##_registered =                                    \
      list::register_plugin({name, flags, description,                                       \
                             ::cdea::plugin_position<classname>::value,                      \
                             &classname::declare_parameters,                                 \
                             &::cdea::plugin_creator<list, classname>::create});             \
  }
