// Parse tree -> Program: names resolved, calls and types checked (spec sections 2.2-2.4).
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "machines/pikocnc/script/compiled.hpp"

namespace pikocnc::script {

// Throws toolpath::InputError (file:line:column) on the first error.
std::unique_ptr<Program> compile_script(std::string_view text, const std::string& file_name);

}  // namespace pikocnc::script
