#include "machines/registry/registry.hpp"

#include "machines/2xaxiscnc/controller.hpp"
#include "machines/iso/controller.hpp"
#include "machines/pikocnc/model/controller.hpp"
#include "machines/sinumerik/controller.hpp"
#include "toolpath/value.hpp"

namespace machines {

std::span<const Controller* const> controllers() {
  // One line per controller; the first is the default for NC files.
  static const Controller* const all[] = {
      &pikocnc::controller(),
      &twoaxis::controller(),
      &sinumerik::controller(),
      &iso::fanuc(),
      &iso::linuxcnc(),
      &iso::mach3(),
      &iso::grbl(),
  };
  return all;
}

const Controller* find_controller(std::string_view name) {
  for (const Controller* c : controllers())
    for (std::string_view n : c->names())
      if (toolpath::iequals(n, name)) return c;
  return nullptr;
}

const Controller& default_controller() { return *controllers().front(); }

std::string controller_names() {
  std::string out;
  for (const Controller* c : controllers())
    for (std::string_view n : c->names()) {
      if (!out.empty()) out += ", ";
      out += n;
    }
  return out;
}

}  // namespace machines
