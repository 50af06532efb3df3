#pragma once

namespace postproc {
inline constexpr const char* kVersion = "0.1.0";
}
